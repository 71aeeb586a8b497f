#pragma once
// Lesson 03: the FBO pipeline and its draw order (seed 000, sections 3.1 to 3.4, hard cases 15, 16
// and 21).
#include <string>
#include <vector>

#include "app/lesson.hpp"
#include "effects/post/fullscreen_pass.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/shadow/shadow_map.hpp"
#include "lit_scene_pass.hpp"
#include "ui_queue_pass.hpp"

namespace lesson03 {

class FboPipelineLesson final : public fx::Lesson {
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
    void reportFacts(std::vector<std::pair<std::string, std::string>>& facts) const override;

    enum Step { StraightToWindow, Reordered, EachPassSetsItsState, FloatTarget, OneOutputTransform };

private:
    // Step 5: left of this fraction of the width, the scene shader still encodes for the display and
    // the output transform encodes again (the washout); right of it, the fix.
    float washoutSplit_ = 0.5f;

    const fx::Scene* scene_ = nullptr;
    fx::SceneMeshes meshes_;
    fx::ShadowMap shadows_;
    LitScenePass litScene_;
    fx::FullscreenPass copyToWindow_;
    fx::OutputTransformPass outputTransform_;
    UiQueuePass uiQueue_;

    int lastStep_ = 0;
    std::vector<std::string> lastExecuted_;      // the passes that ran last frame, in order
    std::vector<std::string> shadowInherited_;   // the shadow pass's inherited state last frame
    std::string noShadowReason_;                  // why there is no shadow pass, if there is none

    void declareStraightToWindow(fx::FrameGraph& graph, const fx::FrameInfo& frame,
                                 const fx::DeclaredShadowMap& shadow);
    void declareThroughFloatTarget(fx::FrameGraph& graph, const fx::FrameInfo& frame,
                                   const fx::DeclaredShadowMap& shadow);
};

}  // namespace lesson03
