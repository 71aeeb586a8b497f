#pragma once
// Lesson 03: the FBO pipeline and its draw order (the Shader effects chapter, §3.1 to §3.4; its
// hard cases 15 state leaks, 16 viewport leaks and 21 aspect: docs/chapters.md).
#include <string>
#include <vector>

#include "app/lesson.hpp"
#include "effects/post/fullscreen_pass.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/post/ui_queue_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/shadow/shadow_map.hpp"
#include "lit_scene_pass.hpp"

namespace lesson03 {

class FboPipelineLesson final : public fx::Lesson {
public:
    fx::LessonInfo info() const override;
    std::vector<std::string> steps() const override;
    void declareParams(fx::ParamSet& params) override;
    fx::Status init(const fx::Scene& scene) override;
    void buildFrame(fx::FrameGraph& graph, const fx::FrameInfo& frame) override;
    void drawPanel(const fx::FrameInfo& frame) override;
    void facts(fx::Facts& out, const fx::FrameInfo& frame) const override;

    enum Step { StraightToWindow, Reordered, EachPassSetsItsState, FloatTarget, OneOutputTransform };

private:
    // Step 5: left of this fraction of the width, the scene shader still encodes for the display and
    // the output transform encodes again (the washout); right of it, the fix.
    float washoutSplit_ = 0.5f;
    // Steps 4 and 5: the scene pass keeps the shadow map's viewport (the deliberate bug the graph
    // otherwise rules out by setting every pass's viewport from its target).
    bool viewportBug_ = false;

    fx::Gpu<fx::ShadowMap> shadows_;
    fx::Gpu<LitScenePass> litScene_;
    fx::Gpu<fx::FullscreenPass> copyToWindow_{"common/copy.frag", "to the window"};
    fx::Gpu<fx::OutputTransformPass> outputTransform_;
    fx::Gpu<fx::UiQueuePass> uiQueue_;

    fx::PassGroup shadowPass_;    // the shadow map pass: what state it inherited last frame
    std::string noShadowReason_;  // why there is no shadow pass, if there is none

    // The shadow pass's inherited state in `report`.
    std::vector<std::string> shadowInherited(const fx::FrameReport* report) const;

    void declareStraightToWindow(fx::FrameGraph& graph, const fx::FrameInfo& frame,
                                 const fx::DeclaredShadowMap& shadow);
    void declareThroughFloatTarget(fx::FrameGraph& graph, const fx::FrameInfo& frame,
                                   const fx::DeclaredShadowMap& shadow);
};

}  // namespace lesson03
