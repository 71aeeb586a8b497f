#pragma once
// Lesson 05: radial blur (the Shader effects chapter, §3.6, hard cases 1 to 4, Exercises 03, 04).
#include "app/lesson.hpp"
#include "app/point_drag.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/post/radial_blur.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/scene/scene_work.hpp"

namespace lesson05 {

class RadialBlurLesson final : public fx::Lesson {
public:
    fx::LessonInfo info() const override;
    std::vector<std::string> steps() const override;
    void declareParams(fx::ParamSet& params) override;
    void update(const fx::FrameInfo& frame) override;
    void buildFrame(fx::FrameGraph& graph, const fx::FrameInfo& frame) override;
    void drawPanel(const fx::FrameInfo& frame) override;
    int benchStep() const override { return SampleCount; }
    void facts(fx::Facts& out, const fx::FrameInfo& frame) const override;

    enum Step { FirstVersion, ChapterStart, Guarded, SampleCount };

    // What a step blurs with: the formula, the sample count, and whether the centre sits on a pixel.
    fx::RadialBlurParams paramsForStep(int step) const;

private:
    // Parameters (the chapter's defaults).
    float centreX_ = 0.5f, centreY_ = 0.5f;
    float length_ = 0.02f;
    float start_ = 0.2f;
    int samples_ = 8;

    fx::Gpu<fx::HdrScenePass> scenePass_;
    fx::Gpu<fx::RadialBlur> blur_;
    fx::Gpu<fx::OutputTransformPass> present_;
    fx::PassGroup blurGroup_ = fx::groupNeeding(fx::SceneFeature::radialBlur);
    fx::PointDrag centreDrag_;

    // Whether both blur passes ran in the frame before `frame` (the scene asks for the blur).
    bool blurRan(const fx::FrameInfo& frame) const;
};

}  // namespace lesson05
