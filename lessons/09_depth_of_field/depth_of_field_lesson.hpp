#pragma once
// Lesson 09: depth of field from a physical lens (the Depth of field chapter, docs/chapters.md): a
// framebuffer shown by a full-screen pass, the chapter's naive blur, focusing by moving the camera,
// the thin-lens CoC as a heat map, the chapter's 13-tap physical blur, then a near/far gather with a
// ring kernel at half resolution, and the accumulation reference it is measured against.
#include <string>
#include <vector>

#include "app/lesson.hpp"
#include "effects/dof/depth_of_field.hpp"
#include "effects/dof/dof_reference.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/scene/scene_work.hpp"
#include "scene/thin_lens.hpp"

namespace lesson09 {

class DepthOfFieldLesson final : public fx::Lesson {
public:
    fx::LessonInfo info() const override;
    std::vector<std::string> steps() const override;
    void declareParams(fx::ParamSet& params) override;
    fx::Status init(const fx::Scene& scene) override;
    void buildFrame(fx::FrameGraph& graph, const fx::FrameInfo& frame) override;
    void drawPanel(const fx::FrameInfo& frame) override;
    void facts(fx::Facts& out, const fx::FrameInfo& frame) const override;
    int benchStep() const override { return Beyond; }
    std::string benchReferenceName() const override { return "accumulation"; }
    void setBenchReference(bool on) override { benchReference_ = on; }

    enum Step { Framebuffer, Naive, MovedCamera, PhysicalCamera, ChapterShader, Beyond, Reference };

    // The camera the frame's step draws with (position and projection) at the frame's size.
    fx::Camera cameraFor(const fx::FrameInfo& frame) const;
    // The thin-lens model of the current parameters at the frame's size.
    fx::ThinLensModel lensModel(const fx::FrameInfo& frame) const;
    fx::CocConvention convention() const {
        return chapterCompatible_ ? fx::CocConvention::chapter : fx::CocConvention::corrected;
    }

private:
    bool showsReference(int step) const { return step == Reference || (step == Beyond && benchReference_); }

    // Parameters: the lens starts from the scene's camera.lens, the rest from postEffects.depthOfField.
    float focalLengthMm_ = 31.1769f;  // 60 deg across 36 mm: the chapter's camera
    float sensorWidthMm_ = 36.0f;
    float fNumber_ = 1.4f;
    float focusM_ = 15.264f;
    bool chapterCompatible_ = false;
    float maxCoc_ = 32.0f;
    int taps_ = 22;
    int method_ = 1;      // step 6: 0 the chapter's 13 taps, 1 the gather
    int resolution_ = 1;  // 0 full, 1 half
    int fields_ = 1;      // 0 one average, 1 near and far
    float highlight_ =
        0.0f;  // the reference has no such weighting: 0 by default, so the bench compares like with like
    int referenceSamples_ = 64;
    int toneCurve_ = 2;  // fx::ToneCurve::filmic
    float exposure_ = 1.0f;
    bool benchReference_ = false;

    fx::Scene view_;  // the scene with the step's camera (steps 1 to 3 move it, as the chapter does)
    fx::Gpu<fx::HdrScenePass> scenePass_;
    fx::Gpu<fx::DepthOfField> dof_;
    fx::Gpu<fx::DofReference> reference_;
    fx::Gpu<fx::OutputTransformPass> present_;
    fx::PassGroup dofGroup_ = fx::groupNeeding(fx::SceneFeature::depthOfField);
};

}  // namespace lesson09
