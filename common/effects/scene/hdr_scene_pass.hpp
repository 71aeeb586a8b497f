#pragma once
// The scene drawn lit, in linear HDR, into a float target: the first pass of every post-processing
// lesson (Shader effects §3.4). It declares "scene" on the frame graph, which creates
//   scene.color  RGBA16F, the size of the output: linear light, values above 1 kept for later passes;
//   scene.depth  Depth32F (a texture, so later passes can read it).
// No gamma is applied here: one output transform at the end of the frame encodes for the display.
// What is written is clamped to [0, kSceneHdrMax] with NaN turned to 0 (docs/numbers.md), so no
// infinite or NaN texel can enter the post-processing chain and spread through a blur.
//
//   HdrScenePass scenePass;  // builds its program: the context is current
//   HdrSceneTargets hdr = scenePass.declare(graph, frame.world);
#include "effects/scene/world.hpp"
#include "gl/program.hpp"
#include "render/frame_graph.hpp"

namespace fx {

// The largest value the scene writes. A half float overflows to infinity above 65504; bloom adds
// several blurred levels (each at most this bright) back onto the image, so the scene leaves room
// for about fifteen of them.
inline constexpr float kSceneHdrMax = 4096.0f;

// What an opaque scene draw into a float target depends on, declared by the pass itself: depth test
// and writes (Less), no blending, back faces culled, every channel written; cleared to the scene's
// sky (clamped to [0, kSceneHdrMax]) and depth 1. Every lit scene pass uses it.
PassState hdrSceneState(const Scene& scene);
// The scene's sky as the display shows it (its linear colour clipped to [0, 1] and sRGB-encoded): the
// clear of a target that holds display values, such as the window.
ClearColor displayClearColor(const Scene& scene);

struct HdrSceneTargets {
    TextureHandle color;
    TextureHandle depth;
};

class HdrScenePass {
public:
    // Declares the "scene" pass: `world` drawn at its time. `colorFormat` is scene.color's format: RGBA16F
    // unless a lesson shows what another one costs (RGBA8 clips every value to [0, 1]: a lamp and the sun
    // both store 1, Bloom chapter §1.1).
    HdrSceneTargets declare(FrameGraph& graph, const World& world,
                            TextureFormat colorFormat = TextureFormat::RGBA16F) const;

private:
    gl::ReloadableProgram program_{
        {"effects/scene/scene_hdr.vert", "effects/scene/scene_hdr.frag", {}, {}, "scene (linear HDR)"}};
};

}  // namespace fx
