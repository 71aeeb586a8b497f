#pragma once
// Lesson 05: radial blur (seed 000, section 3.6, hard cases 1 to 4, Exercises 03 and 04).
#include "app/lesson.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/post/radial_blur.hpp"
#include "effects/scene/scene_meshes.hpp"

namespace lesson05 {

class RadialBlurLesson final : public fx::Lesson {
public:
    fx::LessonInfo info() const override;
    std::vector<std::string> steps() const override;
    void declareParams(fx::ParamSet& params) override;
    fx::Status init(const fx::Scene& scene) override;
    void shutdown() override;
    void update(const fx::FrameInfo& frame) override;
    void buildFrame(fx::FrameGraph& graph, const fx::FrameInfo& frame) override;
    std::vector<fx::gl::ReloadableProgram*> programs() override;
    void drawPanel(const fx::FrameInfo& frame) override;
    int benchStep() const override { return SampleCount; }
    void reportFacts(std::vector<std::pair<std::string, std::string>>& facts) const override;

    enum Step { FirstVersion, ChapterStart, Guarded, SampleCount };

    // What a step blurs with: the formula, the sample count, and whether the centre sits on a pixel.
    fx::RadialBlurParams paramsForStep(int step) const;

private:
    // Parameters (the chapter's defaults).
    float centreX_ = 0.5f, centreY_ = 0.5f;
    float length_ = 0.02f;
    float start_ = 0.2f;
    int samples_ = 8;

    const fx::Scene* scene_ = nullptr;
    fx::SceneMeshes meshes_;
    fx::HdrScenePass scenePass_;
    fx::RadialBlur blur_;
    fx::OutputTransformPass present_;
    bool calledFor_ = true;
    std::string notCalledReason_;
    int lastStep_ = 0;
    fx::Size2D lastSize_;
    bool dragging_ = false;
    bool wasDown_ = false;
    double blurMs_ = 0;
};

}  // namespace lesson05
