#pragma once
// Lesson 08: ray-marched clouds (the Clouds chapter: its sections 1.1 to 2.6, pitfalls and hard cases).
#include <cstdint>
#include <string>
#include <vector>

#include "app/lesson.hpp"
#include "effects/clouds/cloud_march.hpp"
#include "effects/clouds/cloud_pass.hpp"
#include "effects/clouds/cloud_shadow_pass.hpp"
#include "effects/clouds/cloud_temporal.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/shadow/shadow_lit_pass.hpp"
#include "effects/shadow/shadow_map.hpp"

namespace lesson08 {

class CloudsLesson final : public fx::Lesson {
public:
    fx::LessonInfo info() const override;
    std::vector<std::string> steps() const override;
    void declareParams(fx::ParamSet& params) override;
    fx::Status init(const fx::Scene& scene) override;
    void simulations(fx::SceneWork& work) override;
    void update(const fx::FrameInfo& frame) override;
    void buildFrame(fx::FrameGraph& graph, const fx::FrameInfo& frame) override;
    void drawPanel(const fx::FrameInfo& frame) override;
    int benchStep() const override { return Beyond; }
    // Step 9's cloud layer as laid over the scene (full size unless marched at half resolution).
    std::string benchTexture() const override { return "clouds.result"; }
    void facts(fx::Facts& out, const fx::FrameInfo& frame) const override;

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
        fx::CloudDither dither;
        bool accumulate;
        bool halfResolution;
    };
    // The knobs in effect in step 9: the preset's when one is chosen, else the parameters'.
    QualityPreset quality() const;

    // What the cloud pass does in `step` (without the camera, which buildFrame adds).
    fx::CloudFrameSettings settingsForStep(int step, int frameIndex) const;

private:
    // Parameters; the slab, scales, threshold and samples start at the scene's first cloud layer.
    float bottom_ = 0.0f;
    float top_ = 2.0f;
    float scale0_ = 1.0f / 311.0f;
    float scale1_ = 1.0f / 127.0f;
    float threshold_ = 0.5f;
    float steps_ = 8.0f;  // a float on purpose: the overlay can ask for 8.5 (hard case 10)
    bool rejectBehind_ = true;
    float cameraLift_ = 0.0f;
    int dither_ = int(fx::CloudDither::ign);
    bool beerLambert_ = true;
    bool distanceOcclusion_ = true;
    bool cloudShadows_ = true;  // step 9: the clouds' shadows on the ground
    int accumulate_ = 1;        // step 9: 0 off, 1 on
    int resolution_ = 0;        // step 9: 0 full, 1 half

    int quality_ = 0;  // step 9: 0 the knobs above, else one of kQualityPresets

    // What restarts the running average when it changes (everything but the camera and the jitter).
    std::uint64_t settingsKey(const fx::CloudFrameSettings& s, int step) const;

    fx::Scene viewScene_;  // the scene with the camera lifted by camera_lift (the same for every pass)
    fx::ShadowSettings sceneShadow_;
    fx::Gpu<fx::ShadowMap> shadows_;
    fx::Gpu<fx::ShadowLitPass> lit_;
    fx::Gpu<fx::CloudPass> clouds_;
    fx::Gpu<fx::CloudShadowPass> cloudShadow_;
    glm::vec3 sunDirection_{0.0f, -1.0f, 0.0f};  // where the shadow-casting light travels
    fx::CloudDensityTexture density_;            // loaded only when the scene has a cloud layer
    fx::Gpu<fx::OutputTransformPass> present_;
    fx::Gpu<fx::CloudTemporal> temporal_;
    int jitterFrame_ = 0;  // counts declared frames: moves IGN and R2 (the bench repeats one frame index)
    fx::CloudScroll scroll_;
    glm::dvec4 scrollSpeed_{0.0};
    glm::vec3 cloudColour_{1.0f};
    fx::PassGroup cloudGroup_ = fx::groupNeeding(fx::SceneFeature::clouds);
};

}  // namespace lesson08
