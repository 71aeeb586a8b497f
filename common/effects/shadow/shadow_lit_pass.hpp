#pragma once
// The scene lit in linear HDR with the directional light's shadow: HdrScenePass's job (the same
// targets, formats, clamp and state) with a program that includes shaders/common/shadow_lookup.glsl
// and reads the shadow map. Skinned objects are drawn posed (GpuSkinning), so the lit picture and
// the shadow map show one pose.
//
//   DeclaredShadowMap map = shadows.declare(graph, frame.world, settings, {});
//   HdrSceneTargets hdr = lit.declare(graph, frame.world, map);
//
// declareLightView() draws the same scene from the light into "shadow.light_view" for the
// inspector: what the shadow map "sees", in colour. From there every visible surface is lit, which
// is a quick check that the bias and the fit are right.
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "effects/scene/hdr_scene_pass.hpp"
#include "effects/shadow/shadow_map.hpp"

namespace fx {

struct ShadowLitOptions {
    std::string passName = "scene";
    std::string prefix = "scene";  // the targets: <prefix>.color and <prefix>.depth
    // End with the display encoding instead of linear light: right for a draw straight into the
    // window, the double-gamma washout once a later pass encodes again (the FBO pipeline lesson shows
    // both). A target is then cleared to the sky's display value, so all it holds is encoded alike.
    bool encodeForDisplay = false;
    // Skinned objects drawn at each placement (empty: once, where they are), as ShadowPassOptions does.
    std::vector<glm::mat4> skinnedPlacements;
    // A viewport other than the target's (the FBO pipeline lesson's deliberate bug: the shadow map's).
    std::optional<Viewport> viewport;
};

class ShadowLitPass {
public:
    GLuint program() const { return program_.name(); }

    // Declares "scene" (scene.color RGBA16F, scene.depth Depth32F, the output's size). Skinned objects
    // are drawn at each of `skinnedPlacements` (empty: once, where they are), as ShadowPassOptions does.
    HdrSceneTargets declare(FrameGraph& graph, const World& world, const DeclaredShadowMap& shadow,
                            const std::vector<glm::mat4>& skinnedPlacements = {}) const;
    // The same, named and encoded as `options` say.
    HdrSceneTargets declare(FrameGraph& graph, const World& world, const DeclaredShadowMap& shadow,
                            const ShadowLitOptions& options) const;
    // The draw alone (what it reads, its taps, its program), with neither a target nor a state: for a
    // lesson that draws the lit scene where and as it chooses (the FBO pipeline lesson's window).
    Pass& declareDraw(FrameGraph& graph, const World& world, const DeclaredShadowMap& shadow,
                      const ShadowLitOptions& options) const;

    // Declares "shadow light view": the scene from the light, `size` squared, only when inspected.
    TextureHandle declareLightView(FrameGraph& graph, const World& world, const DeclaredShadowMap& shadow,
                                   const std::vector<glm::mat4>& skinnedPlacements = {},
                                   int size = 512) const;

private:
    gl::ReloadableProgram program_{{"effects/shadow/shadowed_scene.vert",
                                    "effects/shadow/shadowed_scene.frag",
                                    {},
                                    {},
                                    "scene with shadows (linear HDR)"}};
};

}  // namespace fx
