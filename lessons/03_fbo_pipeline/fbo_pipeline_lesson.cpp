// Lesson 03: the FBO pipeline and its draw order (the Shader effects chapter, §3.1 to §3.4; its
// hard cases 15 state leaks, 16 viewport leaks and 21 aspect: docs/chapters.md).
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

#include "app/lesson.hpp"
#include "app/runner.hpp"
#include "base/log.hpp"
#include "chapter_order.hpp"
#include "effects/post/copy_pass.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/post/ui_queue_pass.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/shadow/shadow_lit_pass.hpp"
#include "effects/shadow/shadow_map.hpp"

namespace lesson03 {

using namespace fx;

class FboPipelineLesson final : public Lesson {
public:
    std::vector<std::string> steps() const override;
    void declareParams(ParamSet& params) override;
    Status init(const Scene& scene) override;
    void buildFrame(FrameGraph& graph, const FrameInfo& frame) override;
    void drawPanel(const FrameInfo& frame) override;
    void facts(Facts& out, const FrameInfo& frame) const override;

    enum Step { StraightToWindow, Reordered, EachPassSetsItsState, FloatTarget, OneOutputTransform };

private:
    // Step 5: left of this fraction of the width, the scene shader still encodes for the display and
    // the output transform encodes again (the washout); right of it, the fix.
    float washoutSplit_ = 0.5f;
    // Steps 4 and 5: the scene pass keeps the shadow map's viewport (the deliberate bug the graph
    // otherwise rules out by setting every pass's viewport from its target).
    bool viewportBug_ = false;

    Gpu<ShadowMap> shadows_;
    Gpu<ShadowLitPass> litScene_;  // the scene lit by the sun, with its shadow
    Gpu<CopyPass> copyToWindow_{"to the window"};
    Gpu<OutputTransformPass> outputTransform_;
    Gpu<UiQueuePass> uiQueue_;

    PassGroup shadowPass_;        // the shadow map pass: what state it inherited last frame
    std::string noShadowReason_;  // why there is no shadow pass, if there is none

    // The shadow pass's inherited state in `report`.
    std::vector<std::string> shadowInherited(const FrameReport* report) const;

    void declareStraightToWindow(FrameGraph& graph, const FrameInfo& frame, const DeclaredShadowMap& shadow);
    void declareThroughFloatTarget(FrameGraph& graph, const FrameInfo& frame,
                                   const DeclaredShadowMap& shadow);
};

namespace {

// The chapter's frame state from section 3.2 step 3: depth testing and alpha blending for every 3D
// draw that follows, set once at the start of the frame.
PassState chapterDrawState(const Scene& scene) {
    return {.depthTest = true,
            .depthWrite = true,
            .depthFunction = DepthFunction::Less,
            .blend = true,
            .blendFunction = BlendFunction::alpha(),
            .colorMask = ColorMask{},
            .clearColor = displayClearColor(scene),
            .clearDepth = 1.0f};
}

}  // namespace

std::vector<std::string> FboPipelineLesson::steps() const {
    return {
        "Straight to the window",
        "Reordered: the shadows vanish",
        "Each pass sets the state it depends on",
        "Into a float target, one pass to the window",
        "Double gamma, and one output transform",
    };
}

void FboPipelineLesson::declareParams(ParamSet& params) {
    params.addFloat("washout_split", &washoutSplit_, 0.0f, 1.0f).inSteps({OneOutputTransform});
    params.addBool("viewport_bug", &viewportBug_).inSteps({FloatTarget, OneOutputTransform});
}

Status FboPipelineLesson::init(const Scene& scene) {
    noShadowReason_ =
        shadowCastingLight(scene) ? "" : "the scene has no directional light that casts shadows";
    return Status::success();
}

void FboPipelineLesson::buildFrame(FrameGraph& graph, const FrameInfo& frame) {
    ShadowSettings settings;
    if (const Light* sun = shadowCastingLight(frame.world.scene())) settings = sun->shadow;
    ShadowPassOptions options;
    // Until section 3.3 the chapter's CreateShadowMap sets no state: it relies on the frame's.
    options.setsItsOwnState = frame.step >= EachPassSetsItsState;

    if (frame.step == StraightToWindow) {
        // The chapter's old order: the draw state is set before the shadow map is created.
        Pass& setup = graph.addPass("clear + draw state", [](PassContext&) {});
        setup.writeColor(graph.output()).setState(chapterDrawState(frame.world.scene())).setTaps(0);
        DeclaredShadowMap shadow = shadows_->declare(graph, frame.world, settings, options);
        if (shadow.pass) shadow.pass->joinGroup(shadowPass_);
        declareStraightToWindow(graph, frame, shadow);
        return;
    }
    DeclaredShadowMap shadow = shadows_->declare(graph, frame.world, settings, options);
    if (shadow.pass) shadow.pass->joinGroup(shadowPass_);
    if (frame.step == Reordered) {
        Pass& setup = graph.addPass("clear + draw state", [](PassContext&) {});
        setup.writeColor(graph.output()).setState(chapterDrawState(frame.world.scene())).setTaps(0);
        declareStraightToWindow(graph, frame, shadow);
    } else if (frame.step == EachPassSetsItsState) {
        declareStraightToWindow(graph, frame, shadow);
    } else {
        declareThroughFloatTarget(graph, frame, shadow);
    }
}

void FboPipelineLesson::declareStraightToWindow(FrameGraph& graph, const FrameInfo& frame,
                                                const DeclaredShadowMap& shadow) {
    ShadowLitOptions options;
    options.encodeForDisplay = true;  // the window is the last stop: the chapter's standard.frag encodes
    Pass& scene = litScene_->declareDraw(graph, frame.world, shadow, options);
    if (frame.step >= EachPassSetsItsState) {
        // The state it draws with, and the clear of the window: the sky as the display shows it.
        PassState state = hdrSceneState(frame.world.scene());
        state.clearColor = displayClearColor(frame.world.scene());
        scene.setState(state).writeColor(graph.output());
    } else {
        // Steps 1 and 2 draw with the frame's draw state and into the window the setup pass cleared.
        scene.modify(graph.output(), TextureUsage::ColorAttachment);
    }
    uiQueue_->declare(graph, frame.size);
}

void FboPipelineLesson::declareThroughFloatTarget(FrameGraph& graph, const FrameInfo& frame,
                                                  const DeclaredShadowMap& shadow) {
    ShadowLitOptions sceneOptions;
    // The chapter binds a framebuffer and sets its viewport in one go; forget the second half after
    // the shadow map and the scene is drawn into a 2048x2048 viewport on a smaller target: only the
    // bottom-left corner of the picture lands in it. The graph sets every pass's viewport from its
    // target, so here the bug has to be declared on purpose.
    if (viewportBug_ && shadow.pass)
        sceneOptions.viewport = Viewport{0, 0, shadow.settings.mapSize, shadow.settings.mapSize};
    if (frame.step == FloatTarget) {
        sceneOptions.encodeForDisplay = true;  // as in steps 1 to 3: the target holds display values
        HdrSceneTargets main = litScene_->declare(graph, frame.world, shadow, sceneOptions);
        copyToWindow_->declare(graph, "to the window", main.color);
    } else {
        HdrSceneTargets linear = litScene_->declare(graph, frame.world, shadow, sceneOptions);
        std::optional<SplitView> split;
        if (washoutSplit_ > 0.0f) {
            // The same scene, its shader still encoding: what the chapter saw before the fix. Only
            // for the left of the divider; a benchmark frame would not draw it.
            ShadowLitOptions washedOut;
            washedOut.passName = "scene (shader encodes too)";
            washedOut.prefix = "scene_encoded";
            washedOut.encodeForDisplay = true;
            HdrSceneTargets encoded = litScene_->declare(graph, frame.world, shadow, washedOut);
            split = SplitView{encoded.color, washoutSplit_};
        }
        outputTransform_->declare(graph, linear.color, split);
    }
    uiQueue_->declare(graph, frame.size);
}

std::vector<std::string> FboPipelineLesson::shadowInherited(const FrameReport* report) const {
    if (!report) return {};
    std::vector<const PassRecord*> shadow = shadowPass_.records(*report);
    return shadow.empty() ? std::vector<std::string>{} : shadow.front()->stateInherited;
}

void FboPipelineLesson::drawPanel(const FrameInfo& frame) {
    const std::vector<std::string> executed =
        frame.previousFrame ? frame.previousFrame->executedPasses() : std::vector<std::string>{};
    ImGui::TextUnformatted(say("text.frameOrder").c_str());
    if (!ImGui::BeginTable("order", 2, ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchProp))
        return;
    ImGui::TableSetupColumn(say("text.chapterColumn").c_str());
    ImGui::TableSetupColumn(say("text.graphColumn").c_str());
    ImGui::TableHeadersRow();
    const std::vector<ChapterLine>& lines = chapterOrder(frame.step);
    std::size_t rows = std::max(lines.size(), executed.size());
    for (std::size_t i = 0; i < rows; ++i) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        if (i < lines.size()) {
            // The chapter's line in the language shown (steps 4 and 5 share one list of lines).
            const std::string text =
                words().textOr(cat("chapter.", std::min(frame.step, 3) + 1, ".", i + 1), lines[i].text);
            ImGui::TextWrapped("%s%s%s%s", text.c_str(), lines[i].pass.empty() ? "" : " [",
                               lines[i].pass.c_str(), lines[i].pass.empty() ? "" : "]");
        }
        ImGui::TableNextColumn();
        if (i < executed.size()) ImGui::Text("%d. %s", int(i) + 1, executed[i].c_str());
    }
    ImGui::EndTable();
    ImGui::TextWrapped("%s", say("text.graphOrders").c_str());
}

void FboPipelineLesson::facts(Facts& out, const FrameInfo& frame) const {
    // The two orders are the panel's table; the report has them for the draw-order check.
    out.check("chapterPassOrder", joinedNames(chapterPassOrder(frame.step)));
    out.check("executedPassOrder", joinedNames(frame.previousFrame ? frame.previousFrame->executedPasses()
                                                                   : std::vector<std::string>{}));
    std::vector<std::string> inherited = shadowInherited(frame.previousFrame);
    out.addAs("shadowPassInherits", inherited.empty() ? "shadowPassInheritsNothing" : "shadowPassInherits",
              joinedNames(inherited));
    if (!noShadowReason_.empty()) out.add("shadowMapNotRun", noShadowReason_);
    if (frame.step >= FloatTarget) {
        std::string target = cat(frame.size.width, "x", frame.size.height);
        bool bug = viewportBug_ && noShadowReason_.empty();
        int map = 0;
        if (const Light* sun = shadowCastingLight(frame.world.scene())) map = sun->shadow.mapSize;
        const WordArgs sizes{{"map", cat(map, "x", map)}, {"target", target}};
        out.add("sceneViewport", say(bug ? "text.viewportBug" : "text.viewportRight", sizes));
    }
}

}  // namespace lesson03

FX_LESSON(lesson03::FboPipelineLesson, "The FBO pipeline and its draw order", "scenes/03_fbo_pipeline.json")
