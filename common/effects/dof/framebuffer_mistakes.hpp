#pragma once
// Lesson 09 step 1's raw-GL mistakes, made on purpose beside the framebuffer fxlab builds (the
// Depth of field chapter's framebuffer pitfalls; the frame graph avoids them by construction, the
// student's own GL will not):
//   an incomplete framebuffer: a colour attachment GL cannot render to (RGB9_E5), or none at all,
//   checked with glCheckNamedFramebufferStatus and never drawn into;
//   "fbo raw target": the scene's colour copied into a texture made as raw GL makes one
//   (glTexImage2D, level 0 only, MIN_FILTER left at its mipmapped default): incomplete, it samples black;
//   "fbo depth shown": the depth texture read through a plain sampler2D, optionally with
//   COMPARE_MODE on (the result is undefined; drivers give the comparison, 0 or 1).
#include <string>

#include "effects/post/fullscreen_pass.hpp"
#include "gl/object.hpp"
#include "render/frame_graph.hpp"

namespace fx {

enum class IncompleteFramebuffer { none, nonRenderableColor, noAttachment };

// What glCheckNamedFramebufferStatus says of a framebuffer built with the mistake, and the message
// fxlab gives for it (gl::checkFramebufferComplete). The objects are deleted again; no GL error.
struct FramebufferCheck {
    std::string status;
    std::string message;
};
FramebufferCheck checkIncompleteFramebuffer(IncompleteFramebuffer kind);

// What step 1 shows: the scene's colour as fxlab's target holds it, or one of the sampling mistakes.
enum class ShownTarget { color, mipmappedMinFilter, depth, depthCompareMode };

class SamplingMistakes {
public:
    SamplingMistakes();
    // The picture `shown` asks for, from the scene's colour and depth ("fbo.shown"); `color` itself
    // for ShownTarget::color.
    TextureHandle declare(FrameGraph& graph, TextureHandle color, TextureHandle depth, ShownTarget shown,
                          Size2D size);

private:
    FullscreenPass copy_{"common/copy.frag", "fbo copy"};
    FullscreenPass depth_{"effects/dof/show_depth.frag", "fbo depth shown"};
    gl::SamplerName compare_;
    gl::TextureName rawTarget_;  // glTexImage2D's texture, remade at each new size
    Size2D rawSize_{0, 0};
};

}  // namespace fx
