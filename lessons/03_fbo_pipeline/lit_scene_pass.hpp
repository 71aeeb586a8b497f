#pragma once
// Lesson 03's 3D draw: the scene lit by the sun with its shadow, either straight into the window (the
// chapter before section 3.4) or into a float colour target with a depth texture (section 3.4 on).
// Two choices the chapter's steps turn on and off:
//  - encodeForDisplay: standard.frag's final gamma (right for the window, the washout once a
//    full-screen pass encodes again);
//  - declaresState: whether the pass sets the depth, blend and culling state it draws with, or relies
//    on the frame's "draw state" set earlier, as the chapter's Render() does until section 3.3.
#include <optional>
#include <string>

#include "effects/scene/hdr_scene_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/shadow/shadow_map.hpp"
#include "gl/program.hpp"
#include "render/frame_graph.hpp"

namespace lesson03 {

struct LitSceneOptions {
    std::string passName = "scene";
    bool encodeForDisplay = false;
    bool declaresState = true;
    // Clear the target first (the pass creates it). Off when an earlier pass cleared the window.
    bool clears = true;
    // A viewport the pass declares instead of its target's size: the deliberate bug of the viewport
    // toggle (the shadow map's, left over as if nobody set it for the scene's framebuffer).
    std::optional<fx::Viewport> viewport;
};

class LitScenePass {
public:
    // Into the graph's output (the window).
    fx::Pass& declareIntoWindow(fx::FrameGraph& graph, const fx::World& world,
                                const fx::DeclaredShadowMap& shadow, const LitSceneOptions& options) const;
    // Into `<prefix>.color` (RGBA16F, the output's size) and `<prefix>.depth` (Depth32F), cleared.
    fx::HdrSceneTargets declareIntoTargets(fx::FrameGraph& graph, const fx::World& world,
                                           const fx::DeclaredShadowMap& shadow,
                                           const LitSceneOptions& options, const std::string& prefix) const;

    // The colour the window is cleared to: the scene's (linear) sky as the display shows it.
    static fx::ClearColor windowClearColor(const fx::Scene& scene);

private:
    fx::gl::ReloadableProgram program_{{"effects/shadow/shadowed_scene.vert",
                                        "lessons/03_fbo_pipeline/scene_lit.frag",
                                        {},
                                        {},
                                        "scene (lit, shadowed)"}};

    fx::Pass& addPass(fx::FrameGraph& graph, const fx::World& world, const fx::DeclaredShadowMap& shadow,
                      const LitSceneOptions& options) const;
};

}  // namespace lesson03
