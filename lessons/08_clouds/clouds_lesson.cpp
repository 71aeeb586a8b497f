// Lesson 08: ray-marched clouds (the Clouds chapter: its sections 1.1 to 2.6, pitfalls and hard cases).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <imgui.h>
#include <glm/trigonometric.hpp>

#include "app/lesson.hpp"
#include "app/runner.hpp"
#include "base/log.hpp"
#include "effects/clouds/cloud_march.hpp"
#include "effects/clouds/cloud_pass.hpp"
#include "effects/clouds/cloud_shadow_pass.hpp"
#include "effects/clouds/cloud_temporal.hpp"
#include "effects/post/fullscreen_pass.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/scene/camera_matrices.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/shadow/shadow_lit_pass.hpp"
#include "effects/shadow/shadow_map.hpp"
#include "scene/scene_settings.hpp"

namespace fx::glsl {
#include "shaders/lessons/08_clouds/sky_depth_bindings.glsl"
}  // namespace fx::glsl

namespace lesson08 {

using namespace fx;

class CloudsLesson final : public Lesson {
public:
    std::vector<std::string> steps() const override;
    void declareParams(ParamSet& params) override;
    Status init(const Scene& scene) override;
    void simulations(SceneWork& work) override;
    void update(const FrameInfo& frame) override;
    void buildFrame(FrameGraph& graph, const FrameInfo& frame) override;
    void drawPanel(const FrameInfo& frame) override;
    int benchStep() const override { return Beyond; }
    // Step 9's cloud layer as laid over the scene (full size unless marched at half resolution).
    std::string benchTexture() const override { return "clouds.result"; }
    void facts(Facts& out, const FrameInfo& frame) const override;

    enum Step {
        ScreenTexture,
        Plane,
        TwoScales,
        DepthAware,
        March,
        EyeInsideDither,
        Shadows,
        ThresholdHeight,
        Beyond,
    };

    // A combination of the quality knobs, named for the bench's error-against-cost plot.
    struct QualityPreset {
        const char* name;
        float steps;
        CloudDither dither;
        bool accumulate;
        bool halfResolution;
    };
    // The knobs in effect in step 9: the preset's when one is chosen, else the parameters'.
    QualityPreset quality() const;

    // What the cloud pass does in `step` (without the camera, which buildFrame adds).
    CloudFrameSettings settingsForStep(int step, int frameIndex) const;

private:
    // Parameters; the slab, scales, threshold and samples are the scene's first cloud layer's settings.
    float bottom_, top_;
    float scale0_, scale1_;
    float threshold_;
    float steps_;  // a float on purpose: the overlay can ask for 8.5 (hard case 10)
    bool rejectBehind_ = true;
    float cameraLift_ = 0.0f;
    Choice<CloudDither> dither_{CloudDither::ign};
    bool beerLambert_ = true;
    bool distanceOcclusion_ = true;
    bool cloudShadows_ = true;  // step 9: the clouds' shadows on the ground
    int accumulate_ = 1;        // step 9: 0 off, 1 on
    int resolution_ = 0;        // step 9: 0 full, 1 half

    int quality_ = 0;  // step 9: 0 the knobs above, else one of kQualityPresets
    // Pitfalls shown on purpose, each off by default.
    float skyDistance_ = 0.0f;     // steps 4 to 9: a sky at this distance writes depth (0: none)
    bool depthLookupBug_ = false;  // step 9 at half resolution: depth read at the layer's own pixels
    bool mipmaps_ = false;         // the density at the level of the pixel's footprint (the fix)

    // What restarts the running average when it changes (everything but the camera and the jitter).
    std::uint64_t settingsKey(const CloudFrameSettings& s, int step) const;

    Scene viewScene_;  // the scene with the camera lifted by camera_lift (the same for every pass)
    ShadowSettings sceneShadow_;
    Gpu<ShadowMap> shadows_;
    Gpu<ShadowLitPass> lit_;
    Gpu<CloudPass> clouds_;
    Gpu<CloudShadowPass> cloudShadow_;
    glm::vec3 sunDirection_{0.0f, -1.0f, 0.0f};  // where the shadow-casting light travels
    CloudDensityTexture density_;                // loaded only when the scene has a cloud layer
    CloudDensityTexture mipmappedDensity_;       // the same file with every level, loaded for mipmaps
    std::string densityPath_;
    Gpu<FullscreenPass> skyDepth_{"lessons/08_clouds/sky_depth.frag", "clouds: sky that writes depth"};
    // The depth sky_distance writes: where a point that far ahead lands in [0, 1] (1: no sky pass).
    float skyDepthValue(const CameraMatrices& camera) const;
    Gpu<OutputTransformPass> present_;
    Gpu<CloudTemporal> temporal_;
    int jitterFrame_ = 0;  // counts declared frames: moves IGN and R2 (the bench repeats one frame index)
    CloudScroll scroll_;
    glm::dvec4 scrollSpeed_{0.0};
    glm::vec3 cloudColour_{1.0f};
    PassGroup cloudGroup_ = groupNeeding(SceneFeature::clouds);
};

namespace {

// Index 0 is "the knobs": every knob at its reference is the bench's reference picture (512 samples,
// no jitter, no accumulation, full resolution). The others are the combinations the lesson compares
// with the chapter's 8 samples and Bayer dither.
const CloudsLesson::QualityPreset kQualityPresets[] = {
    {"knobs", 0, CloudDither::none, false, false},
    {"8 Bayer (chapter)", 8, CloudDither::bayer, false, false},
    {"8 IGN", 8, CloudDither::ign, false, false},
    {"8 IGN acc", 8, CloudDither::ign, true, false},
    {"4 IGN acc", 4, CloudDither::ign, true, false},
    {"2 IGN acc", 2, CloudDither::ign, true, false},
    {"4 R2 acc", 4, CloudDither::r2, true, false},
    {"4 IGN acc half", 4, CloudDither::ign, true, true},
    {"8 IGN acc half", 8, CloudDither::ign, true, true},
    {"16 IGN acc half", 16, CloudDither::ign, true, true},
    {"32 none", 32, CloudDither::none, false, false},
    {"100 none", 100, CloudDither::none, false, false},
};
constexpr int kQualityPresetCount = int(sizeof kQualityPresets / sizeof kQualityPresets[0]);

}  // namespace

CloudsLesson::QualityPreset CloudsLesson::quality() const {
    if (quality_ > 0 && quality_ < kQualityPresetCount) return kQualityPresets[quality_];
    return {"knobs", steps_, *dither_, accumulate_ == 1, resolution_ == 1};
}

std::vector<std::string> CloudsLesson::steps() const {
    return {
        "The density texture on the screen",
        "An infinite plane, and hits behind the eye",
        "Two scales, scrolled over time",
        "Depth-aware: the world position from depth",
        "Ray marching the slab, 8 samples: banding",
        "The eye inside the layer, and a 4x4 Bayer dither",
        "Object shadows on the clouds",
        "Threshold and height shaping",
        "Beyond the chapter: moving jitter, Beer-Lambert steps, distance occlusion, cloud shadows",
    };
}

void CloudsLesson::declareParams(ParamSet& params) {
    params.addSetting("bottom", &bottom_, sceneSetting("clouds[0].bottom"));
    params.addSetting("top", &top_, sceneSetting("clouds[0].top"));
    params.addSetting("scale0", &scale0_, sceneSetting("clouds[0].noise[0].scale"));
    params.addSetting("scale1", &scale1_, sceneSetting("clouds[0].noise[1].scale"));
    params.addSetting("threshold", &threshold_, sceneSetting("clouds[0].threshold"))
        .inSteps({ThresholdHeight, Beyond});
    // A float on purpose: the overlay can ask for 8.5 samples (rounded down; hard case 10).
    Param& steps = params.addSetting("steps", &steps_, sceneSetting("clouds[0].steps"));
    steps.knob = Knob{{2, 4, 8, 16, 32, 64, 128}, double(kCloudMaxSteps), "samples"};
    steps.inSteps({March, EyeInsideDither, Shadows, ThresholdHeight, Beyond});
    params.addBool("reject_behind", &rejectBehind_).inSteps({Plane});
    params.addFloat("camera_lift", &cameraLift_, -20.0f, 20.0f);
    Param& dither = params.addChoice("dither", &dither_, {"none", "bayer", "ign", "r2"});
    dither.knob = Knob{{0, 1, 2, 3}, 0, "dither"};
    dither.inSteps({Beyond});
    Param& accumulate = params.addChoice("accumulate", &accumulate_, {"off", "on"});
    accumulate.knob = Knob{{0, 1}, 0, "accumulation"};
    accumulate.inSteps({Beyond});
    Param& resolution = params.addChoice("resolution", &resolution_, {"full", "half"});
    resolution.knob = Knob{{0, 1}, 0, "resolution"};
    resolution.inSteps({Beyond});
    std::vector<std::string> presetNames;
    std::vector<double> presetValues;
    for (int i = 0; i < kQualityPresetCount; ++i) {
        presetNames.push_back(kQualityPresets[i].name);
        presetValues.push_back(i);
    }
    Param& preset = params.addChoice("quality", &quality_, presetNames);
    preset.knob = Knob{presetValues, 0, "combination"};
    preset.inSteps({Beyond});
    params.addBool("beer_lambert", &beerLambert_).inSteps({Beyond});
    params.addBool("distance_occlusion", &distanceOcclusion_).inSteps({Beyond});
    params.addFloat("sky_distance", &skyDistance_, 0.0f, 1000.0f)
        .showZeroAs()
        .inSteps({DepthAware, March, EyeInsideDither, Shadows, ThresholdHeight, Beyond});
    params.addBool("depth_lookup_bug", &depthLookupBug_).inSteps({Beyond});
    params.addBool("mipmaps", &mipmaps_)
        .inSteps({Plane, TwoScales, DepthAware, March, EyeInsideDither, Shadows, ThresholdHeight, Beyond});
    params.addBool("cloud_shadow", &cloudShadows_).inSteps({Beyond});
}

Status CloudsLesson::init(const Scene& scene) {
    viewScene_ = scene;
    if (const Light* light = shadowCastingLight(scene)) {
        sceneShadow_ = light->shadow;
        sunDirection_ = light->direction;
    }
    if (!scene.clouds.empty()) {
        // Only a scene with a cloud layer loads the texture: without one, no bytes and no pass.
        const CloudLayer& layer = scene.clouds.front();
        densityPath_ = layer.densityTexture.resolved.string();
        auto loaded = CloudDensityTexture::load(densityPath_);
        if (!loaded) return Error{cat("clouds[0].densityTexture: ", loaded.error())};
        density_ = std::move(*loaded);
        scrollSpeed_ = glm::dvec4(layer.noise[0].scroll.x, layer.noise[0].scroll.y, layer.noise[1].scroll.x,
                                  layer.noise[1].scroll.y);
        cloudColour_ = layer.color;
    }
    return Status::success();
}

void CloudsLesson::simulations(SceneWork& work) {
    // The scroll, wrapped every frame (cloud_march.hpp: a 200-hour run moves like the first minute).
    work.onUpdate(Simulation::clouds, "cloud scroll",
                  [this](const SimulationStep& s) { scroll_.advance(scrollSpeed_, s.deltaSeconds); });
}

void CloudsLesson::update(const FrameInfo& frame) {
    viewScene_.camera = frame.world.scene().camera;
    viewScene_.camera.position.y += cameraLift_;
    if (viewScene_.camera.aim == CameraAim::target) viewScene_.camera.target.y += cameraLift_;
}

CloudFrameSettings CloudsLesson::settingsForStep(int step, int frameIndex) const {
    CloudFrameSettings s;
    s.frameIndex = frameIndex;
    s.march = cloudMarch(bottom_, top_, steps_, threshold_);
    s.planeHeight = 0.5f * (bottom_ + top_);
    s.scales = {scale0_, scale1_};
    s.scrollOffset = scroll_.offset();
    s.color = cloudColour_;
    int f = 0;
    switch (step) {
        case ScreenTexture:
            s.stage = CloudStage::screenTexture;
            break;
        case Plane:
            s.stage = CloudStage::plane;
            f = rejectBehind_ ? cloudRejectBehind : 0;
            s.scrollOffset = glm::vec4(0.0f);  // one layer, standing still: the scroll comes in step 3
            break;
        case TwoScales:
            s.stage = CloudStage::plane;
            f = cloudRejectBehind | cloudTwoScales;
            break;
        case DepthAware:
            s.stage = CloudStage::plane;
            f = cloudRejectBehind | cloudTwoScales | cloudDepthAware;
            break;
        case March:
            f = cloudTwoScales | cloudDepthAware;
            break;
        case EyeInsideDither:
            f = cloudTwoScales | cloudDepthAware | cloudEyeInside;
            s.dither = CloudDither::bayer;
            break;
        case Shadows:
            f = cloudTwoScales | cloudDepthAware | cloudEyeInside | cloudShadows;
            s.dither = CloudDither::bayer;
            break;
        case ThresholdHeight:
            f = cloudTwoScales | cloudDepthAware | cloudEyeInside | cloudShadows | cloudThreshold |
                cloudHeightShaping;
            s.dither = CloudDither::bayer;
            break;
        default: {  // Beyond
            f = cloudTwoScales | cloudDepthAware | cloudEyeInside | cloudShadows | cloudThreshold |
                cloudHeightShaping;
            if (beerLambert_) f |= cloudBeerLambert;
            if (distanceOcclusion_) f |= cloudDistanceOcclusion;
            QualityPreset q = quality();
            s.dither = q.dither;
            s.march = cloudMarch(bottom_, top_, q.steps, threshold_);
            break;
        }
    }
    s.features = f;
    s.mipmaps = mipmaps_ && step != ScreenTexture;
    s.depthAtLayerPixels = depthLookupBug_ && step == Beyond;
    return s;
}

float CloudsLesson::skyDepthValue(const CameraMatrices& camera) const {
    if (!(skyDistance_ > 0.0f)) return 1.0f;
    const glm::vec4 clip = camera.projection * glm::vec4(0.0f, 0.0f, -skyDistance_, 1.0f);
    return std::clamp(0.5f * clip.z / clip.w + 0.5f, 0.0f, 1.0f);
}

void CloudsLesson::buildFrame(FrameGraph& graph, const FrameInfo& frame) {
    const Scene& scene = viewScene_;
    const World world = frame.world.seenThrough(viewScene_);
    ShadowSettings settings = sceneShadow_;
    DeclaredShadowMap map = shadows_->declare(graph, world, settings, {});
    HdrSceneTargets hdr = lit_->declare(graph, world, map);

    CloudFrameSettings s = settingsForStep(frame.step, jitterFrame_);
    jitterFrame_ = (jitterFrame_ + 1) % 1024;
    // The same matrices the scene pass drew with (cameraMatrices at the output's size).
    CameraMatrices camera = cameraMatrices(scene.camera, frame.size.width, frame.size.height);
    const float skyDepth = skyDepthValue(camera);
    if (skyDepth < 1.0f && frame.step >= DepthAware) {
        // The mistake sky_distance shows: the sky drawn like an object, writing depth where nothing else
        // did (depth test LESS against the clear value 1), no colour.
        const FullscreenPass* sky = &*skyDepth_;
        PassState state = FullscreenPass::state();
        state.depthTest = true;
        state.depthWrite = true;
        state.depthFunction = DepthFunction::Less;
        state.colorMask = ColorMask{false, false, false, false};
        sky->addPass(graph, "sky (writes depth)",
                     [sky, skyDepth](PassContext&) {
                         glProgramUniform1f(sky->program(), glsl::kSkyDepthLocation, skyDepth);
                         sky->draw({});
                     })
            .modify(hdr.depth, TextureUsage::DepthAttachment)
            .setState(state)
            .setTaps(0);
    }
    if (mipmaps_ && !mipmappedDensity_ && !densityPath_.empty()) {
        auto loaded = CloudDensityTexture::load(densityPath_, true);
        if (loaded)
            mipmappedDensity_ = std::move(*loaded);
        else
            log::error("lesson 08: clouds[0].densityTexture: ", loaded.error());
    }
    const CloudDensityTexture& density = s.mipmaps && mipmappedDensity_ ? mipmappedDensity_ : density_;
    s.mipmaps = s.mipmaps && mipmappedDensity_;
    s.view = camera.view;
    s.projection = camera.projection;
    s.cameraPosition = camera.position;
    {
        PassGroup::Scope in(graph, cloudGroup_);  // runs only when the scene has a cloud layer
        const QualityPreset q = quality();
        // Step 9 always marches into a layer of its own ("clouds.result", what the bench compares).
        // Without a cloud layer the direct pass is declared (and not called for): no textures at all.
        const bool temporal = frame.step == Beyond && !lacks(graph, SceneFeature::clouds);
        // The ground darkened under the clouds before the clouds are laid over it (not the clouds).
        // Declared without a cloud layer too: the group shows both passes as not called for.
        if (frame.step == Beyond && cloudShadows_) {
            CloudShadowSettings shadow;
            shadow.toLight = cloudShadowToLight(sunDirection_);
            cloudShadow_->declare(graph, {hdr.color, hdr.depth}, density, s, shadow);
        }
        if (temporal) {
            CloudTemporalOptions options{q.accumulate, q.halfResolution};
            temporal_->declare(graph, *clouds_, {hdr.color, hdr.depth, &map}, density, s, options,
                               settingsKey(s, frame.step), frame.size);
        } else {
            clouds_->declare(graph, {hdr.color, hdr.depth, &map}, density, s);
        }
    }
    shadows_->declareDepthView(graph, map);
    present_->declare(graph, hdr.color);
}

std::uint64_t CloudsLesson::settingsKey(const CloudFrameSettings& s, int step) const {
    // FNV-1a over the numbers that change the picture (not the camera, which is reprojected, nor the
    // jitter, which is what the average is for).
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&h](double v) {
        std::uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        for (int i = 0; i < 8; ++i) h = (h ^ ((bits >> (8 * i)) & 0xff)) * 1099511628211ull;
    };
    for (double v : {double(step), double(s.features), double(s.dither), double(s.march.steps),
                     double(s.march.bottom), double(s.march.top), double(s.march.threshold),
                     double(s.scales.x), double(s.scales.y), double(resolution_), double(cameraLift_),
                     double(s.mipmaps), double(s.depthAtLayerPixels), double(skyDistance_)})
        mix(v);
    return h;
}

void CloudsLesson::drawPanel(const FrameInfo& frame) {
    if (frame.step == Plane && !rejectBehind_) ImGui::TextWrapped("%s", say("text.mirrored").c_str());
    if (frame.step >= March) ImGui::TextWrapped("%s", say("text.cameraLift").c_str());
}

void CloudsLesson::facts(Facts& out, const FrameInfo& frame) const {
    CloudFrameSettings s = settingsForStep(frame.step, jitterFrame_);
    const bool march = s.stage == CloudStage::march;
    out.add("cloudLayer", frame.world.scene().clouds.empty() ? "none" : "first of the scene's");
    out.add("densityTextureBytes", std::to_string(density_.bytes()));
    if (march) {
        out.add("samples", std::to_string(s.march.steps));
        out.add("stepHeight", cat(s.march.stepHeight));
        out.add("dither", cloudDitherName(s.dither));
    }
    if (frame.step >= ThresholdHeight) out.add("thresholdGain", cat(s.march.thresholdGain));
    if (frame.step == Beyond) {
        // The running average weighs a new frame 1/16 at least: past 16 frames it holds 16 frames' worth.
        const int averaged = std::min(temporal_->framesAveraged(), CloudTemporalOptions{}.maxFrames);
        out.add("framesAveraged", std::to_string(averaged));
        out.add("historyBytes", std::to_string(temporal_->historyBytes()));
        out.add("quality", quality().name);
        out.add("resolution", quality().halfResolution ? "half" : "full");
        // The sun's height decides the shadow's path through the slab (thickness / sin, sin held at 0.1 or
        // more).
        const float sunDegrees =
            glm::degrees(std::asin(std::clamp(cloudShadowToLight(sunDirection_).y, -1.0f, 1.0f)));
        out.add("cloudShadow", cloudShadows_ ? cat("on, sun ", sunDegrees, " degrees up") : "off");
    }
    if (mipmappedDensity_) out.add("mipmappedDensityBytes", std::to_string(mipmappedDensity_.bytes()));
    if (frame.step >= DepthAware) {
        const CameraMatrices camera = cameraMatrices(viewScene_.camera, frame.size.width, frame.size.height);
        out.add("skyDepth", cat(skyDepthValue(camera)));
    }
    if (frame.step == Beyond && quality().halfResolution)
        out.add("depthTexelsPerPixel",
                depthLookupBug_ ? "1 (the mistake: the target is half the depth's size)" : "2");
    glm::vec4 o = scroll_.offset();
    out.add("scrollOffset", cat("(", o.x, ", ", o.y, ", ", o.z, ", ", o.w, ")"));
    if (frame.previousFrame) out.add("cloudMs", cat(cloudGroup_.timeMs(*frame.previousFrame)));
}

}  // namespace lesson08

FX_LESSON(lesson08::CloudsLesson, "Ray-marched clouds", "scenes/08_clouds.json")
