#pragma once
// Render to texture (Deferred rendering chapter, the FBO recipes): a framebuffer object the lesson
// builds itself, the slides' way, at their fixed 512 x 512, with a colour texture and either
//  - a depth renderbuffer (only the depth test needs it; nobody can sample it), or
//  - a depth texture (what later steps need: the G-buffer's positions are rebuilt from depth).
// The frame graph makes framebuffers for its passes itself; this one is built by hand to show the
// recipe, so its colour (and depth) textures enter the graph as imported textures that the pass
// "render to texture" writes. attachmentsText() is what GL says is attached, asked back from GL.
//
//   RenderToTexture rtt;  // builds the textures, the renderbuffer and both framebuffers
//   TextureHandle color = rtt.declare(graph, frame.world, RttDepth::renderbuffer);
#include <string>

#include "effects/scene/world.hpp"
#include "gl/framebuffer.hpp"
#include "gl/program.hpp"
#include "gl/texture.hpp"
#include "render/frame_graph.hpp"

namespace fx {

enum class RttDepth { renderbuffer = 0, texture = 1 };

inline constexpr int kRttSize = 512;  // the slides' compile-time width and height

class RenderToTexture {
public:
    RenderToTexture();

    // Declares "render to texture", which draws the scene lit (the lecture's Phong terms, summed) into
    // "rtt.color" (RGBA8, 512 x 512, imported) with the chosen depth attachment. With a depth texture,
    // "rtt.depth" (Depth32F) is imported too, so the inspector can show it. Returns rtt.color.
    TextureHandle declare(FrameGraph& graph, const World& world, RttDepth depth) const;

    // "colour 0: texture rtt.color RGBA8 512x512; depth: renderbuffer GL_DEPTH_COMPONENT24", read
    // back from GL with glGetNamedFramebufferAttachmentParameteriv.
    std::string attachmentsText(RttDepth depth) const;
    GLuint framebuffer(RttDepth depth) const;

private:
    gl::ReloadableProgram program_{{"effects/deferred/lit_scene.vert",
                                    "effects/deferred/phong.frag",
                                    {},
                                    {},
                                    "render to texture (Phong, summed)"}};
    gl::Texture color_ = gl::Texture::create2D(TextureFormat::RGBA8, kRttSize, kRttSize, 1, "rtt.color");
    gl::Texture depthTexture_ =
        gl::Texture::create2D(TextureFormat::Depth32F, kRttSize, kRttSize, 1, "rtt.depth");
    gl::RenderbufferName depthRenderbuffer_ = gl::createRenderbuffer("rtt.depth (renderbuffer)");
    gl::Framebuffer withRenderbuffer_{"rtt: colour texture + depth renderbuffer"};
    gl::Framebuffer withTexture_{"rtt: colour texture + depth texture"};
};

// What framebuffer `fbo` has attached, asked back from GL: one entry per colour attachment 0..7 that
// has an image, and depth, each "texture <label> <format> WxH" or "renderbuffer <internal format>".
std::string describeAttachments(GLuint fbo);

}  // namespace fx
