// Lesson 02: skeletal-mesh shadows (the Shader effects chapter, §2; hard cases 17, 19, 20).
#include <algorithm>
#include <cmath>
#include <vector>

#include <imgui.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>

#include "app/lesson.hpp"
#include "app/runner.hpp"
#include "base/log.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/shadow/shadow_lit_pass.hpp"
#include "effects/shadow/shadow_map.hpp"

namespace lesson02 {

using namespace fx;

class SkinnedShadowsLesson final : public Lesson {
public:
    std::vector<std::string> steps() const override;
    void declareParams(ParamSet& params) override;
    Status init(const Scene& scene) override;
    void buildFrame(FrameGraph& graph, const FrameInfo& frame) override;
    void drawPanel(const FrameInfo& frame) override;
    int benchStep() const override { return ProductOrder; }  // the crowd: every knob has work to show
    void facts(Facts& out, const FrameInfo& frame) const override;

    enum Step { StaticCastersOnly, SkinnedCasters, ProductOrder, ErrorFlood, CutoutShadows };

    // What the shadow pass does in a step (public so tests can build the same frame).
    ShadowPassOptions shadowOptionsForStep(int step, bool benchmark) const;
    // The crowd of step 3: where each copy of the character stands (the first is where it is).
    static std::vector<glm::mat4> crowdPlacements(int count);

private:
    // Parameters; map size and taps start at the scene's values (res/scenes/02_skinned_shadows.json).
    int mapSize_ = 2048;
    int filterTaps_ = 16;
    float filterRadius_ = 0.03f;
    int productOrder_ = 1;  // 0: (T*J)*p, 1: T*(J*p)
    int crowd_ = 16;
    int materialUpload_ = 0;  // 0: always (the chapter's flood), 1: ask the program
    int cutoffUniform_ = 0;   // 0: first program only (the chapter's bug), 1: every program

    ShadowSettings sceneShadow_;
    Gpu<ShadowMap> shadows_;
    Gpu<ShadowLitPass> lit_;
    Gpu<OutputTransformPass> present_;

    // Filled while the frame executes (the pass bodies write them), read by the panel and report.
    mutable ShadowPassStats stats_;
    ShadowPassStats otherStats_;
    // The shadow pass, and in step 3 the one drawing with the other product: timed side by side.
    PassGroup shadowPass_, otherProductPass_;
};

namespace {

// Crowd spacing: characters a little more than a shoulder width apart, rows behind one another.
constexpr float kCrowdSpacingX = 1.1f;
constexpr float kCrowdSpacingZ = 1.3f;

}  // namespace

std::vector<std::string> SkinnedShadowsLesson::steps() const {
    return {
        "Only static meshes cast shadows",
        "A shadow program for skinned meshes",
        "T*(J*p) against (T*J)*p, with a crowd",
        "The GL error flood, and asking the program",
        "Alpha-cutout shadows: one cutoff per program",
    };
}

void SkinnedShadowsLesson::declareParams(ParamSet& params) {
    Param& size = params.addInt("map_size", &mapSize_, 16, 8192);
    size.knob = Knob{{256, 512, 1024, 2048}, 4096, "texels"};
    Param& taps = params.addInt("filter_taps", &filterTaps_, 1, kShadowMaxFilterTaps);
    taps.knob = Knob{{1, 4, 8, 16, 32}, 64, "taps"};
    params.addFloat("filter_radius", &filterRadius_, 0.0f, 0.5f);
    Param& order = params.addChoice("product_order", &productOrder_, {"(T*J)*p", "T*(J*p)"});
    order.knob = Knob{{0, 1}, 1, "order"};
    order.inSteps({ProductOrder});
    params.addInt("crowd", &crowd_, 1, 400).inSteps({ProductOrder});
    params.addChoice("material_upload", &materialUpload_, {"always", "ask_program"}).inSteps({ErrorFlood});
    params.addChoice("cutoff_uniform", &cutoffUniform_, {"first_program_only", "every_program"})
        .inSteps({CutoutShadows});
}

Status SkinnedShadowsLesson::init(const Scene& scene) {
    if (const Light* light = shadowCastingLight(scene)) sceneShadow_ = light->shadow;
    return Status::success();
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
        case ErrorFlood:
            o.materialUpload = materialUpload_ == 0 ? MaterialUpload::always : MaterialUpload::askProgram;
            break;
        default:  // CutoutShadows
            o.cutoff = cutoffUniform_ == 0 ? CutoffUniform::firstProgramOnly : CutoffUniform::everyProgram;
            break;
    }
    return o;
}

void SkinnedShadowsLesson::buildFrame(FrameGraph& graph, const FrameInfo& frame) {
    ShadowSettings settings = sceneShadow_;
    settings.casts = true;
    settings.mapSize = mapSize_;
    settings.filterTaps = filterTaps_;

    ShadowPassOptions options = shadowOptionsForStep(frame.step, frame.benchmark);
    DeclaredShadowMap map = shadows_->declare(graph, frame.world, settings, options);
    if (map.pass) map.pass->joinGroup(shadowPass_);

    // Step 3: the other product draws the same crowd into its own map, so both times stand side by
    // side every frame. A bench frame measures the chosen one alone.
    if (frame.step == ProductOrder && !frame.benchmark && map.pass) {
        ShadowPassOptions other = options;
        other.product = options.product == SkinningProduct::grouped ? SkinningProduct::parenthesised
                                                                    : SkinningProduct::grouped;
        other.passName = "shadow map (other product)";
        other.textureName = "shadow.map_other_product";
        other.stats = &otherStats_;
        DeclaredShadowMap compared = shadows_->declare(graph, frame.world, settings, map.lookup.light, other);
        if (compared.pass) compared.pass->keepAlive().joinGroup(otherProductPass_);
    }

    HdrSceneTargets hdr = lit_->declare(graph, frame.world, map, options.skinnedPlacements);
    shadows_->declareDepthView(graph, map);
    lit_->declareLightView(graph, frame.world, map, options.skinnedPlacements);
    present_->declare(graph, hdr.color);
}

void SkinnedShadowsLesson::drawPanel(const FrameInfo& frame) {
    if (frame.step == ProductOrder) {
        ImGui::TextWrapped("%s", say("text.jointBlend").c_str());
    }
    if (frame.step == CutoutShadows) {
        ImGui::TextWrapped("%s", say(cutoffUniform_ == 0 ? "text.cutoffFirstOnly" : "text.cutoffEvery",
                                     {{"cutoff", cat(std::round(kAlphaCutoff * 10.0f) / 10.0f)}})
                                     .c_str());
    }
    if (frame.step == ErrorFlood) {
        ImGui::TextWrapped("%s", say(materialUpload_ == 0 ? "text.uploadAlways" : "text.uploadAsk").c_str());
    }
}

void SkinnedShadowsLesson::facts(Facts& out, const FrameInfo& frame) const {
    const ShadowPassStats& s = stats_;
    out.add("shadowMapSize", std::to_string(mapSize_));
    out.add("filterTaps", std::to_string(filterTaps_));
    out.add("staticShadowDraws", std::to_string(s.staticDraws));
    out.add("skinnedShadowDraws", std::to_string(s.skinnedDraws));
    out.add("shadowProgramSwitches", std::to_string(s.programSwitches));
    out.add("skinnedShadowVertices", std::to_string(s.skinnedVertices));
    if (frame.step == ErrorFlood) {
        out.add("shadowPassGlErrorsLastFrame", std::to_string(s.glErrors));
    } else {
        out.check("shadowPassGlErrorsLastFrame", std::to_string(s.glErrors));
    }
    double shadowMs = frame.previousFrame ? shadowPass_.timeMs(*frame.previousFrame) : 0;
    double otherMs = frame.previousFrame ? otherProductPass_.timeMs(*frame.previousFrame) : 0;
    if (frame.step == ProductOrder) {
        const bool groupedShown = productOrder_ == 0;
        for (SkinningProduct p : {SkinningProduct::grouped, SkinningProduct::parenthesised}) {
            const bool grouped = p == SkinningProduct::grouped;
            OperationCount c = operationCount(p);
            out.add(grouped ? "opsGroupedPerVertex" : "opsParenthesisedPerVertex",
                    std::to_string(c.mul + c.add),
                    {{"mul", cat(c.mul)},
                     {"add", cat(c.add)},
                     {"ms", cat(grouped == groupedShown ? shadowMs : otherMs)}});
        }
    } else if (frame.previousFrame) {
        out.add("shadowMs", cat(shadowMs));
    }
    if (frame.step == CutoutShadows)
        out.add("alphaCutoffOnSkinnedProgram",
                cutoffUniform_ == 0 ? say("text.neverSet") : cat(kAlphaCutoff));
    // Step 4 exists to show GL errors (counted as expected); the smoke test checks that it does.
    out.check("expectErrorsInStep", frame.step == ErrorFlood && materialUpload_ == 0);
}

}  // namespace lesson02

FX_LESSON(lesson02::SkinnedShadowsLesson, "Skeletal-mesh shadows", "scenes/02_skinned_shadows.json")
