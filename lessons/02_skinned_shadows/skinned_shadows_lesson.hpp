#pragma once
// Lesson 02: skeletal-mesh shadows (the Shader effects chapter, §2; hard cases 17, 19, 20).
#include <vector>

#include <glm/mat4x4.hpp>

#include "app/lesson.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/shadow/shadow_lit_pass.hpp"
#include "effects/shadow/shadow_map.hpp"

namespace lesson02 {

class SkinnedShadowsLesson final : public fx::Lesson {
public:
    fx::LessonInfo info() const override;
    std::vector<std::string> steps() const override;
    void declareParams(fx::ParamSet& params) override;
    fx::Status init(const fx::Scene& scene) override;
    void buildFrame(fx::FrameGraph& graph, const fx::FrameInfo& frame) override;
    void drawPanel(const fx::FrameInfo& frame) override;
    int benchStep() const override { return ProductOrder; }  // the crowd: every knob has work to show
    void facts(fx::Facts& out, const fx::FrameInfo& frame) const override;

    enum Step { StaticCastersOnly, SkinnedCasters, ProductOrder, ErrorFlood, CutoutShadows };

    // What the shadow pass does in a step (public so tests can build the same frame).
    fx::ShadowPassOptions shadowOptionsForStep(int step, bool benchmark) const;
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

    fx::ShadowSettings sceneShadow_;
    fx::Gpu<fx::ShadowMap> shadows_;
    fx::Gpu<fx::ShadowLitPass> lit_;
    fx::Gpu<fx::OutputTransformPass> present_;

    // Filled while the frame executes (the pass bodies write them), read by the panel and report.
    mutable fx::ShadowPassStats stats_;
    fx::ShadowPassStats otherStats_;
    // The shadow pass, and in step 3 the one drawing with the other product: timed side by side.
    fx::PassGroup shadowPass_, otherProductPass_;
};

}  // namespace lesson02
