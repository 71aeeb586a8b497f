#pragma once
// The lecture's multiple render targets (Deferred rendering chapter, the three-target example): one
// fragment shader writes diffuse, specular and ambient light into three RGBA8 targets at once, and a
// full-screen pass adds them. Then the slides' edge-enhancement variant, which sharpens the diffuse
// term with the 4-neighbour kernel (identity minus the Laplacian) and writes the sum to an RGBA8 and a
// float target at once, to show the [-4, 5] range clipped in one and kept in the other.
//
// The slides restore the draw buffer with glDrawBuffer(GL_BACK) while their framebuffer object is
// still bound. GL_BACK is no buffer of a framebuffer object, so GL answers GL_INVALID_OPERATION, and
// nothing needed restoring anyway: the draw-buffer list belongs to the framebuffer object (the frame
// graph sets it once when it makes the framebuffer). MrtOrder::slides reproduces the call, inside a
// gl::ExpectedErrorScope, and counts the errors; MrtOrder::fixed leaves it out.
#include <cstdint>

#include "effects/post/fullscreen_pass.hpp"
#include "effects/scene/world.hpp"
#include "gl/program.hpp"
#include "render/frame_graph.hpp"

namespace fx {

enum class MrtOrder { fixed, slides };

// The lecture's light on a program that has scene_uniforms.glsl, after SceneMeshes::setFrameUniforms:
// white (1, 1, 1) from the scene's sun direction and ambient 0.2, the companion code's constants, so the
// lecture's steps look like the lecture whatever the scene's own light levels (its sun may be a moon).
void setLectureLight(GLuint program);

struct MrtTargets {
    TextureHandle diffuse;   // "mrt.diffuse"  RGBA8
    TextureHandle specular;  // "mrt.specular" RGBA8
    TextureHandle ambient;   // "mrt.ambient"  RGBA8, alpha 1 where a surface is
    TextureHandle depth;     // "mrt.depth"    Depth32F
};

struct SharpenTargets {
    TextureHandle clipped;  // "sharpen.rgba8": the sum, clipped to [0, 1] by the format
    TextureHandle kept;     // "sharpen.float" (RGBA16F): the same sum, kept
};

// What the MRT pass did when it last ran (for the overlay).
struct MrtStats {
    std::int64_t orderErrors = 0;  // GL errors the slides' glDrawBuffer(GL_BACK) raised, all runs
    std::int64_t lastFrameErrors = 0;
};

class LectureMrt {
public:
    // "mrt": the scene's Phong terms into three targets (cleared to 0) plus depth. `stats` must outlive
    // the frame's execution (it may be null).
    MrtTargets declare(FrameGraph& graph, const World& world, MrtOrder order, MrtStats* stats) const;
    // "mrt composite": D + S + A, and the sky where no surface is, into "mrt.sum" (RGBA16F).
    TextureHandle declareComposite(FrameGraph& graph, const Scene& scene, const MrtTargets& targets) const;
    // "mrt sharpen": the slides' variant, into both sharpen targets at once (two colour attachments).
    SharpenTargets declareSharpen(FrameGraph& graph, const Scene& scene, const MrtTargets& targets) const;
    // "sharpen range": the float target's values above 1 in red, below 0 in blue, over the 8-bit one
    // in grey, into "sharpen.range" (RGBA16F).
    TextureHandle declareRangeView(FrameGraph& graph, const SharpenTargets& sharpened) const;

private:
    gl::ReloadableProgram phong_{{"effects/deferred/lit_scene.vert",
                                  "effects/deferred/phong.frag",
                                  {},
                                  "#define THREE_TARGETS 1",
                                  "mrt (diffuse, specular, ambient)"}};
    FullscreenPass composite_{"effects/deferred/mrt_composite.frag", "mrt composite"};
    FullscreenPass sharpen_{"effects/deferred/mrt_composite.frag", "mrt sharpen", "#define SHARPEN 1"};
    FullscreenPass range_{"effects/deferred/sharpen_range.frag", "sharpen range"};
};

}  // namespace fx
