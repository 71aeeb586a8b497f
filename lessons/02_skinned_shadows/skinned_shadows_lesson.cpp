#include "skinned_shadows_lesson.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <imgui.h>


namespace lesson02 {

using namespace fx;

namespace {

// Crowd spacing: characters a little more than a shoulder width apart, rows behind one another.
constexpr float kCrowdSpacingX = 1.1f;
constexpr float kCrowdSpacingZ = 1.3f;

double passMs(const FrameInfo& frame, const char* name, double previous) {
    if (!frame.previousFrame) return previous;
    const auto* pass = frame.previousFrame->findPass(name);
    return (pass && pass->timeMs) ? *pass->timeMs : previous;
}

}  // namespace

LessonInfo SkinnedShadowsLesson::info() const {
    return {2, "skinned-shadows", "Skeletal-mesh shadows", "scenes/02_skinned_shadows.json"};
}

std::vector<std::string> SkinnedShadowsLesson::steps() const {
    return {
        "Only static meshes cast shadows",
        "A shadow program for skinned meshes",
        "T*(J*p) against (T*J)*p, with a crowd",
        "The GL error flood, and asking the program",
    };
}

void SkinnedShadowsLesson::declareParams(ParamSet& params) {
    Param& size = params.addInt("map_size", &mapSize_, 16, 8192,
                                "Shadow map texels per side (the scene asks for 2048); memory grows with the square");
    size.knob = Knob{{256, 512, 1024, 2048}, 4096, "texels"};
    Param& taps = params.addInt("filter_taps", &filterTaps_, 1, kShadowMaxFilterTaps,
                                "PCF depth comparisons per pixel (1: a hard, stair-stepped edge)");
    taps.knob = Knob{{1, 4, 8, 16, 32}, 64, "taps"};
    params.addFloat("filter_radius", &filterRadius_, 0.0f, 0.5f,
                    "PCF disc radius in metres, the same at every map size (0: 1.5 texels of the map)");
    Param& order = params.addChoice("product_order", &productOrder_, {"(T*J)*p", "T*(J*p)"},
                                    "Step 3: the skinning product of the shadow map the scene uses");
    order.knob = Knob{{0, 1}, 1, "order"};
    params.addInt("crowd", &crowd_, 1, 400, "Step 3: characters in the crowd (a grid; the first is the scene's)");
    params.addChoice("material_upload", &materialUpload_, {"always", "ask_program"},
                     "Step 4: upload material uniforms to the skinned shadow program always (the chapter's "
                     "GL error flood) or only if the program has them (the fix)");
}

Status SkinnedShadowsLesson::init(const Scene& scene) {
    scene_ = &scene;
    if (const Light* light = shadowCastingLight(scene)) sceneShadow_ = light->shadow;
    meshes_ = SceneMeshes(scene);
    shadows_ = ShadowMap::create();
    lit_ = ShadowLitPass::create();
    present_ = OutputTransformPass::create();
    for (auto* p : programs()) {
        if (!p->usable()) return Error{p->error()};
    }
    return Status::success();
}

void SkinnedShadowsLesson::shutdown() {
    *this = SkinnedShadowsLesson();
}

std::vector<gl::ReloadableProgram*> SkinnedShadowsLesson::programs() {
    std::vector<gl::ReloadableProgram*> out = shadows_.programs();
    out.push_back(lit_.reloadable());
    out.push_back(present_.reloadable());
    return out;
}

std::vector<glm::mat4> SkinnedShadowsLesson::crowdPlacements(int count) {
    std::vector<glm::mat4> out;
    count = std::max(count, 1);
    int perRow = int(std::ceil(std::sqrt(double(count))));
    for (int i = 0; i < count; ++i) {
        int column = i % perRow, row = i / perRow;
        // Columns alternate right and left of the original, rows go back from it: copy 0 is the original.
        float side = (column % 2 == 1) ? -1.0f : 1.0f;
        float x = side * float((column + 1) / 2) * kCrowdSpacingX;
        float z = -float(row) * kCrowdSpacingZ;
        out.push_back(glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.0f, z)));
    }
    return out;
}

ShadowPassOptions SkinnedShadowsLesson::shadowOptionsForStep(int step, bool benchmark) const {
    (void)benchmark;
    ShadowPassOptions o;
    o.filterRadiusMetres = filterRadius_;
    o.stats = &stats_;  // written by the pass body while the frame executes
    switch (step) {
        case StaticCastersOnly:
            o.drawSkinned = false;  // the chapter before section 2: skinned objects are skipped
            break;
        case SkinnedCasters:
            break;
        case ProductOrder:
            o.product = productOrder_ == 0 ? SkinningProduct::grouped : SkinningProduct::parenthesised;
            o.skinnedPlacements = crowdPlacements(crowd_);
            break;
        default:  // ErrorFlood
            o.materialUpload = materialUpload_ == 0 ? MaterialUpload::always : MaterialUpload::askProgram;
            break;
    }
    return o;
}

void SkinnedShadowsLesson::update(const FrameInfo& frame) {
    meshes_.update(frame.seconds);  // animation and GPU skinning, once a frame
}

void SkinnedShadowsLesson::buildFrame(FrameGraph& graph, const FrameInfo& frame) {
    lastStep_ = frame.step;
    const Scene& scene = *scene_;
    ShadowSettings settings = sceneShadow_;
    settings.casts = true;
    settings.mapSize = mapSize_;
    settings.filterTaps = filterTaps_;

    ShadowPassOptions options = shadowOptionsForStep(frame.step, frame.benchmark);
    DeclaredShadowMap map = shadows_.declare(graph, scene, meshes_, frame.seconds, settings, options);

    // Step 3: the other product draws the same crowd into its own map, so both times stand side by
    // side every frame. A bench frame measures the chosen one alone.
    if (frame.step == ProductOrder && !frame.benchmark && map.pass) {
        ShadowPassOptions other = options;
        other.product = options.product == SkinningProduct::grouped ? SkinningProduct::parenthesised
                                                                    : SkinningProduct::grouped;
        other.passName = "shadow map (other product)";
        other.textureName = "shadow.map_other_product";
        other.stats = &otherStats_;
        DeclaredShadowMap compared =
            shadows_.declare(graph, scene, meshes_, frame.seconds, settings, map.lookup.light, other);
        compared.pass->keepAlive();
    }

    HdrSceneTargets hdr = lit_.declare(graph, scene, meshes_, frame.seconds, map, options.skinnedPlacements);
    shadows_.declareDepthView(graph, map);
    lit_.declareLightView(graph, scene, meshes_, frame.seconds, map, options.skinnedPlacements);
    present_.declare(graph, hdr.color);

    shadowMs_ = passMs(frame, "shadow map", shadowMs_);
    otherMs_ = passMs(frame, "shadow map (other product)", otherMs_);
}

void SkinnedShadowsLesson::drawPanel(const FrameInfo& frame) {
    const ShadowPassStats& s = stats_;
    ImGui::Text("shadow map: %dx%d Depth32F, %d PCF taps, pass %.3f ms", mapSize_, mapSize_, filterTaps_, shadowMs_);
    ImGui::Text("draws: %zu static, %zu skinned; program switches: %d", s.staticDraws, s.skinnedDraws,
                s.programSwitches);
    if (frame.step == ProductOrder) {
        auto line = [&](SkinningProduct p, double ms) {
            OperationCount c = operationCount(p);
            double vertices = double(s.skinnedVertices);
            ImGui::Text("%s: %d mul + %d add a vertex, %.2f M ops over %.0f vertices, %.3f ms",
                        p == SkinningProduct::grouped ? "(T*J)*p" : "T*(J*p)", c.mul, c.add,
                        vertices * (c.mul + c.add) / 1e6, vertices, ms);
        };
        bool groupedShown = productOrder_ == 0;
        line(SkinningProduct::grouped, groupedShown ? shadowMs_ : otherMs_);
        line(SkinningProduct::parenthesised, groupedShown ? otherMs_ : shadowMs_);
        ImGui::TextWrapped("Both include the 4 scalar*mat4 and 3 mat4 additions of the joint blend, which "
                           "the parentheses do not change.");
    }
    if (frame.step == ErrorFlood) {
        ImGui::Text("GL errors from the skinned shadow draws this frame: %lld", static_cast<long long>(s.glErrors));
        ImGui::TextWrapped("material upload: %s", materialUpload_ == 0
                                                      ? "always (GL_INVALID_OPERATION per upload: the flood)"
                                                      : "only if the program has the uniform (none here: no errors)");
    }
}

void SkinnedShadowsLesson::reportFacts(std::vector<std::pair<std::string, std::string>>& facts) const {
    facts.emplace_back("shadowMapSize", std::to_string(mapSize_));
    facts.emplace_back("filterTaps", std::to_string(filterTaps_));
    facts.emplace_back("staticShadowDraws", std::to_string(stats_.staticDraws));
    facts.emplace_back("skinnedShadowDraws", std::to_string(stats_.skinnedDraws));
    facts.emplace_back("shadowProgramSwitches", std::to_string(stats_.programSwitches));
    facts.emplace_back("skinnedShadowVertices", std::to_string(stats_.skinnedVertices));
    facts.emplace_back("shadowPassGlErrorsLastFrame", std::to_string(stats_.glErrors));
    if (lastStep_ == ProductOrder) {
        facts.emplace_back("opsGroupedPerVertex", std::to_string(operationCount(SkinningProduct::grouped).mul +
                                                                 operationCount(SkinningProduct::grouped).add));
        facts.emplace_back("opsParenthesisedPerVertex",
                           std::to_string(operationCount(SkinningProduct::parenthesised).mul +
                                          operationCount(SkinningProduct::parenthesised).add));
    }
    // Step 4 exists to show GL errors (counted as expected); the smoke test checks that it does.
    bool flood = lastStep_ == ErrorFlood && materialUpload_ == 0;
    facts.emplace_back("expectErrorsInStep", flood ? "true" : "false");
}

}  // namespace lesson02
