// Lesson 10: render to texture, multiple render targets and deferred shading with a thousand lights
// (the Deferred rendering chapter, docs/chapters.md). The slides' framebuffer recipes first, then their
// three-target example with its draw-buffer order bug and its sharpening variant, then what the chapter
// only lists: a G-buffer of geometry, one lighting pass over many point lights, what the G-buffer's
// layout costs, tiled light culling, and the chapter's homework, a planar reflection.
#include <algorithm>
#include <string>
#include <vector>

#include <imgui.h>

#include "app/lesson.hpp"
#include "app/runner.hpp"
#include "base/log.hpp"
#include "effects/deferred/deferred_lighting.hpp"
#include "effects/deferred/gbuffer_pass.hpp"
#include "effects/deferred/lecture_mrt.hpp"
#include "effects/deferred/light_evaluations.hpp"
#include "effects/deferred/per_vertex_lighting.hpp"
#include "effects/deferred/planar_reflection.hpp"
#include "effects/deferred/point_light_buffer.hpp"
#include "effects/deferred/render_to_texture.hpp"
#include "effects/deferred/tiled_culling.hpp"
#include "effects/post/fullscreen_pass.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/shadow/shadow_map.hpp"

namespace lesson10 {

using namespace fx;

class DeferredShadingLesson final : public Lesson {
public:
    std::vector<std::string> steps() const override;
    void declareParams(ParamSet& params) override;
    Status init(const Scene& scene) override;
    void buildFrame(FrameGraph& graph, const FrameInfo& frame) override;
    void facts(Facts& out, const FrameInfo& frame) const override;
    void drawPanel(const FrameInfo& frame) override;
    int benchStep() const override { return Reflection; }
    std::string benchTexture() const override { return "deferred.color"; }

    enum Step { RenderToTexture, ThreeTargets, Sharpen, Deferred, Layout, ManyLights, Reflection };
    // The choices' meanings, in the order of their names.
    enum class OriginOffset { none, km1, km10 };
    enum class Culling { none, tiled };
    enum class ReflectionSize { full, half, quarter };
    enum class Lighting { deferred, perVertex };
    enum class ReflectionClear { sky, chapter };

private:
    // The G-buffer layout, light count and culling the step uses.
    GBufferLayout layoutFor(int step) const;
    bool culls(int step) const { return step >= ManyLights; }
    glm::vec3 worldOffsetFor(int step) const;
    int lightCountFor(int step) const;  // light_count, or the step's own when it is 0
    void uploadLights(const FrameInfo& frame);
    void declareDeferred(FrameGraph& graph, const FrameInfo& frame, TextureHandle& shown,
                         std::optional<SplitView>& split);

    // Parameters.
    Choice<RttDepth> rttDepth_{RttDepth::renderbuffer};
    bool slidesOrder_ = true;  // step 2: the slides' glDrawBuffer(GL_BACK) with the FBO bound
    Choice<GBufferLayout> layout_{GBufferLayout::compact};
    Choice<OriginOffset> originOffset_{OriginOffset::none};
    int lightCount_ = 0;  // 0: the step's own (lightCountFor)
    Choice<Culling> culling_{Culling::tiled};
    Choice<ReflectionSize> reflectionSize_{ReflectionSize::half};
    float reflectionBlur_ = 0.0f;  // step 7: the homework's optional blur (sigma; 0 is off)
    float divider_ = 0.5f;
    // The mistakes the chapter warns about, shown on purpose (off by default).
    Choice<Lighting> lightingModel_{Lighting::deferred};             // step 4
    bool mirrorObjects_ = false;                                     // step 7
    Choice<ReflectionClear> reflectionClear_{ReflectionClear::sky};  // step 7

    std::vector<Light> allLights_;
    int pointLightsInScene_ = 0;
    glm::vec3 uploadedOffset_{-1.0f};
    int uploadedCount_ = -1;
    Gpu<fx::RenderToTexture> rtt_;
    Gpu<FullscreenPass> rttToScreen_{"common/copy.frag", "rtt to screen"};
    Gpu<LectureMrt> mrt_;
    MrtStats mrtStats_;
    Gpu<GBufferPass> gbuffer_;
    Gpu<ShadowMap> shadows_;
    Gpu<PointLightBuffer> lights_;
    Gpu<DeferredLighting> lighting_;
    Gpu<TiledCulling> culling_pass_;
    Gpu<PlanarReflection> reflection_;
    Gpu<PerVertexLighting> perVertex_;
    Gpu<OutputTransformPass> present_;
    std::string rttAttachments_[2];
    PassGroup cullingGroup_;
    PassGroup lightingGroup_;
    PassGroup reflectionGroup_;
};

namespace {

// Step 5 moves the whole world (scene and camera) this far along X: where half floats run out.
float originOffsetM(DeferredShadingLesson::OriginOffset offset) {
    using enum DeferredShadingLesson::OriginOffset;
    switch (offset) {
        case km1:
            return 1000.0f;
        case km10:
            return 10000.0f;
        case none:
            break;
    }
    return 0.0f;
}

// Step 7's reflection target as a fraction of the output: 1/1, 1/2, 1/4.
int reflectionFraction(DeferredShadingLesson::ReflectionSize size) {
    using enum DeferredShadingLesson::ReflectionSize;
    switch (size) {
        case half:
            return 2;
        case quarter:
            return 4;
        case full:
            break;
    }
    return 1;
}

// The chapter's clear colour (the companion repository's), which its reflection target is cleared to:
// where nothing is reflected the floor gets strength x this, a bluish tint.
constexpr glm::vec3 kChapterClearColor(0.1f, 0.2f, 0.3f);
// Steps 4 and 5 light the yard with every other lamp each way: they show one pass over many lights
// (and the G-buffer's layout), and a software renderer pays for every light at every pixel there.
// Step 6 is where the thousand become affordable.
constexpr int kUnculledStepLights = 256;

// `count` of the point lights, spread evenly over where they stand instead of the first `count` (a
// strip of the grid): a light's rank among the distinct x and among the distinct z positions, and
// the lights on the coarsest lattice of those ranks first (for a 32 x 32 grid, 256 is every other
// lamp each way, 64 every fourth). The chosen lights keep their order, and all of them are the list
// as it is.
std::vector<Light> spreadPointLights(const std::vector<Light>& lights, int count) {
    std::vector<std::size_t> points;
    std::vector<float> xs, zs;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        if (lights[i].type != LightType::point) continue;
        points.push_back(i);
        xs.push_back(lights[i].position.x);
        zs.push_back(lights[i].position.z);
    }
    if (count >= int(points.size())) return lights;
    auto ranks = [](std::vector<float> values) {
        std::sort(values.begin(), values.end());
        values.erase(std::unique(values.begin(), values.end()), values.end());
        return values;
    };
    const std::vector<float> xRanks = ranks(xs), zRanks = ranks(zs);
    auto rank = [](const std::vector<float>& sorted, float v) {
        return unsigned(std::lower_bound(sorted.begin(), sorted.end(), v) - sorted.begin());
    };
    auto lattice = [](unsigned a, unsigned b) {  // the largest power of two dividing both (0 counts as any)
        const unsigned both = a | b;
        return both == 0 ? ~0u : both & (~both + 1u);
    };
    std::vector<std::size_t> order = points;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return lattice(rank(xRanks, lights[a].position.x), rank(zRanks, lights[a].position.z)) >
               lattice(rank(xRanks, lights[b].position.x), rank(zRanks, lights[b].position.z));
    });
    order.resize(std::size_t(std::max(count, 0)));
    std::sort(order.begin(), order.end());
    std::vector<Light> chosen;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        if (lights[i].type != LightType::point || std::binary_search(order.begin(), order.end(), i))
            chosen.push_back(lights[i]);
    }
    return chosen;
}

}  // namespace

std::vector<std::string> DeferredShadingLesson::steps() const {
    return {
        "Render to texture: a colour texture and a depth buffer",
        "Three targets at once, and the slides' draw-buffer order bug",
        "The sharpening variant: identity minus the Laplacian",
        "Deferred shading: a G-buffer and one pass over many lights",
        "What the G-buffer layout costs",
        "A thousand lights: tiled culling",
        "The homework: a planar reflection",
    };
}

void DeferredShadingLesson::declareParams(ParamSet& params) {
    params.addChoice("rtt_depth", &rttDepth_, {"renderbuffer", "texture"}).inSteps({RenderToTexture});
    params.addBool("slides_order", &slidesOrder_).inSteps({ThreeTargets});
    Param& layout = params.addChoice("layout", &layout_, gbufferLayoutNames());
    layout.knob = Knob{{0, 1, 2}, 2, "layout"};
    layout.inSteps({Layout, ManyLights, Reflection});
    params.addChoice("origin_offset", &originOffset_, {"0", "1000", "10000"}).inSteps({Layout});
    Param& count = params.addInt("light_count", &lightCount_, 0, kMaxGridLights);
    count.showZeroAs();
    count.knob = Knob{{1, 4, 16, 64, 256, 1024}, 1024, "lights"};
    count.inSteps({Deferred, Layout, ManyLights, Reflection});
    Param& culling = params.addChoice("culling", &culling_, {"none", "tiled"});
    culling.knob = Knob{{0, 1}, 0, "culling"};
    culling.inSteps({ManyLights, Reflection});
    Param& reflection = params.addChoice("reflection_size", &reflectionSize_, {"full", "half", "quarter"});
    reflection.knob = Knob{{0, 1, 2}, 0, "reflection size"};
    reflection.inSteps({Reflection});
    params.addFloat("reflection_blur", &reflectionBlur_, 0.0f, 0.05f).showZeroAs().inSteps({Reflection});
    params.addChoice("lighting", &lightingModel_, {"deferred", "per-vertex"}).inSteps({Deferred});
    params.addBool("mirror_objects", &mirrorObjects_).inSteps({Reflection});
    params.addChoice("reflection_clear", &reflectionClear_, {"sky", "chapter"}).inSteps({Reflection});
    params.addFloat("divider", &divider_, 0.0f, 1.0f).inSteps({Sharpen, Layout, ManyLights});
}

Status DeferredShadingLesson::init(const Scene& scene) {
    allLights_ = allLights(scene);
    pointLightsInScene_ = int(std::count_if(allLights_.begin(), allLights_.end(),
                                            [](const Light& l) { return l.type == LightType::point; }));
    rttAttachments_[0] = rtt_->attachmentsText(RttDepth::renderbuffer);
    rttAttachments_[1] = rtt_->attachmentsText(RttDepth::texture);
    return Status::success();
}

GBufferLayout DeferredShadingLesson::layoutFor(int step) const {
    if (step < Layout) return GBufferLayout::compact;  // step 4: the compact layout the chapter's idea needs
    return *layout_;
}

int DeferredShadingLesson::lightCountFor(int step) const {
    if (lightCount_ > 0) return lightCount_;
    return step < ManyLights ? kUnculledStepLights : kMaxGridLights;
}

glm::vec3 DeferredShadingLesson::worldOffsetFor(int step) const {
    if (step != Layout) return glm::vec3(0.0f);
    return glm::vec3(originOffsetM(*originOffset_), 0.0f, 0.0f);
}

void DeferredShadingLesson::uploadLights(const FrameInfo& frame) {
    // The light list changes only with the parameters: upload it then, not every frame. Called from
    // buildFrame, so bench frames (which change parameters without an update()) see the new list too.
    glm::vec3 offset = worldOffsetFor(frame.step);
    int count = std::clamp(lightCountFor(frame.step), 1, kMaxGridLights);
    if (offset != uploadedOffset_ || count != uploadedCount_) {
        lights_->upload(gpuPointLights(spreadPointLights(allLights_, count), count, offset));
        uploadedOffset_ = offset;
        uploadedCount_ = count;
    }
}

void DeferredShadingLesson::declareDeferred(FrameGraph& graph, const FrameInfo& frame, TextureHandle& shown,
                                            std::optional<SplitView>& split) {
    const Scene& scene = frame.world.scene();
    const int step = frame.step;
    DeclaredShadowMap shadow;
    if (const Light* sun = shadowCastingLight(scene))
        shadow = shadows_->declare(graph, frame.world, sun->shadow, ShadowPassOptions{});

    GBufferOptions options{layoutFor(step), step == Layout && !frame.benchmark, worldOffsetFor(step)};
    GBufferTargets g = gbuffer_->declare(graph, frame.world, options);
    if (!frame.benchmark) lighting_->declareViews(graph, scene, g);

    std::optional<CulledTiles> tiles;
    if (culls(step)) {
        PassGroup::Scope in(graph, cullingGroup_);
        CulledTiles culled = culling_pass_->declare(graph, scene, g, *lights_);
        if (*culling_ == Culling::none) culling_pass_->lastPass()->disable("culling: none (the parameter)");
        // Without many lights the culling pass is not called for (the scene's reason is in the pass
        // table), and every light is evaluated: a handful costs less than a pass that sorts them.
        else if (!lacks(graph, SceneFeature::manyLights))
            tiles = culled;
    }
    TextureHandle lit;
    {
        PassGroup::Scope in(graph, lightingGroup_);
        lit = lighting_->declare(graph, scene, g, *lights_, shadow, tiles);
    }
    shown = lit;
    if (step == Deferred && *lightingModel_ == Lighting::perVertex) {
        shown = perVertex_->declare(graph, frame.world, *lights_);
        return;
    }
    if (step == Reflection) {
        PassGroup::Scope in(graph, reflectionGroup_);
        ReflectionMistakes mistakes{mirrorObjects_, std::nullopt};
        if (*reflectionClear_ == ReflectionClear::chapter) mistakes.clearColor = kChapterClearColor;
        reflection_->declare(graph, frame.world, *lights_, g, lit, reflectionFraction(*reflectionSize_),
                             mistakes, ReflectionBlur{reflectionBlur_});
        return;
    }
    if (step == Layout && options.referencePosition)
        split = SplitView{lighting_->declarePositionError(graph, scene, g), divider_};
    if (tiles && !frame.benchmark)
        split = SplitView{
            culling_pass_->declareHeatMap(graph, *tiles, lit, std::max(lightCountFor(step) / 32, 8)),
            divider_};
}

void DeferredShadingLesson::buildFrame(FrameGraph& graph, const FrameInfo& frame) {
    const Scene& scene = frame.world.scene();
    uploadLights(frame);
    TextureHandle shown;
    std::optional<SplitView> split;
    switch (frame.step) {
        case RenderToTexture: {
            TextureHandle color = rtt_->declare(graph, frame.world, *rttDepth_);
            // The 512 x 512 texture, stretched over the window: sampled in [0, 1], whatever the sizes.
            const FullscreenPass* copy = &*rttToScreen_;
            Pass& pass = rttToScreen_->addPass(
                graph, "rtt to screen", [copy, color](PassContext& ctx) { copy->draw({ctx.native(color)}); });
            pass.read(color).setTaps(1);
            shown = pass.create("rtt.shown", {TextureSize::output(), TextureFormat::RGBA16F, 1},
                                TextureUsage::ColorAttachment);
            break;
        }
        case ThreeTargets: {
            MrtTargets t = mrt_->declare(graph, frame.world,
                                         slidesOrder_ ? MrtOrder::slides : MrtOrder::fixed, &mrtStats_);
            shown = mrt_->declareComposite(graph, scene, t);
            break;
        }
        case Sharpen: {
            MrtTargets t = mrt_->declare(graph, frame.world, MrtOrder::fixed, &mrtStats_);
            SharpenTargets s = mrt_->declareSharpen(graph, scene, t);
            shown = s.clipped;
            split = SplitView{mrt_->declareRangeView(graph, s), divider_};
            break;
        }
        default:
            declareDeferred(graph, frame, shown, split);
            break;
    }
    present_->declare(graph, shown, split);
}

void DeferredShadingLesson::facts(Facts& out, const FrameInfo& frame) const {
    const int step = frame.step;
    out.check("expectErrorsInStep", step == ThreeTargets && slidesOrder_);
    if (step == RenderToTexture) {
        out.add("rttAttachments", rttAttachments_[*rttDepth_ == RttDepth::texture ? 1 : 0]);
        return;
    }
    if (step == ThreeTargets || step == Sharpen) {
        out.add("drawBuffers", "GL_COLOR_ATTACHMENT0, 1, 2 (set once, on the framebuffer object)");
        out.add("orderErrorsLastFrame", std::to_string(mrtStats_.lastFrameErrors));
        out.add("orderErrorsTotal", std::to_string(mrtStats_.orderErrors));
        if (step == Sharpen) out.add("sharpenRange", "[-4, 5] for inputs in [0, 1]");
        return;
    }
    GBufferLayout layout = layoutFor(step);
    long long pixels = (long long)frame.size.width * frame.size.height;
    out.add("layout", toString(layout));
    out.add("bytesPerPixel", std::to_string(gbufferBytesPerPixel(layout)));
    out.add("gbufferMiB", cat(double(pixels * gbufferBytesPerPixel(layout)) / (1024.0 * 1024.0)));
    out.add("pointLights", std::to_string(lights_->count()), {{"scene", cat(pointLightsInScene_)}});
    if (step == Deferred)
        out.add("lighting", *lightingModel_ == Lighting::perVertex ? "per vertex (forward, interpolated)"
                                                                   : "per pixel (deferred)");
    if (step == Layout) {
        float at = std::abs(worldOffsetFor(step).x) + 10.0f;
        out.add("halfFloatStep", cat(halfFloatSpacing(at)), {{"at", cat(at)}});
    }
    if (step == Reflection) {
        auto mirror = findMirror(frame.world.scene(), frame.seconds);
        out.add("mirror", mirror ? frame.world.scene().objects[mirror->object].name : std::string("none"));
        int fraction = reflectionFraction(*reflectionSize_);
        out.add("reflectionMirrors",
                mirrorObjects_ ? "the objects (model x reflection, det -1)" : "the camera");
        out.add("reflectionClear",
                *reflectionClear_ == ReflectionClear::chapter ? "the chapter's (0.1, 0.2, 0.3)" : "the sky");
        out.add("reflectionSize", cat(std::max(frame.size.width / fraction, 1), "x",
                                      std::max(frame.size.height / fraction, 1)));
        out.add("reflectionBlur", reflectionBlur_ > 0.0f ? cat("16 taps, sigma ", reflectionBlur_)
                                                         : std::string("off (one tap)"));
    }
    if (step == ManyLights) {
        Size2D tiles = tileCount(frame.size);
        out.add("tiles", cat(tiles.width, " x ", tiles.height), {{"size", cat(kTileSize)}});
        out.add("naiveEvaluations", cat(naiveLightEvaluations(frame.size, lights_->count())));
    }
    if (frame.previousFrame) {
        out.add("lightingMs", cat(lightingGroup_.timeMs(*frame.previousFrame)));
        if (culls(step)) out.add("cullingMs", cat(cullingGroup_.timeMs(*frame.previousFrame)));
        if (step == Reflection) out.add("reflectionMs", cat(reflectionGroup_.timeMs(*frame.previousFrame)));
        out.add("frameMs", cat(frame.previousFrame->timedMs()));
    }
}

void DeferredShadingLesson::drawPanel(const FrameInfo& frame) {
    switch (frame.step) {
        case RenderToTexture:
            ImGui::TextWrapped("%s", say("text.rttDepth").c_str());
            break;
        case ThreeTargets:
            ImGui::TextWrapped("%s", say("text.threeTargets").c_str());
            break;
        case Sharpen:
            ImGui::TextWrapped("%s", say("text.sharpen").c_str());
            break;
        case Deferred:
            ImGui::TextWrapped("%s", say("text.gbuffer").c_str());
            break;
        case Layout:
            ImGui::TextWrapped("%s", say("text.layout").c_str());
            break;
        case ManyLights:
            ImGui::TextWrapped("%s", say("text.tiles").c_str());
            break;
        default:
            ImGui::TextWrapped("%s", say("text.reflection").c_str());
            break;
    }
    // light_count's slider shows 0 for "the step's own": say what that is, in lights.
    if (frame.step >= Deferred && lightCount_ == 0)
        ImGui::TextWrapped("%s", say("text.stepsOwn", {{"count", cat(lightCountFor(frame.step))}}).c_str());
}

}  // namespace lesson10

FX_LESSON(lesson10::DeferredShadingLesson, "Deferred shading", "scenes/10_deferred_shading.json")
