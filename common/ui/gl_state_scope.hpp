#pragma once
// The overlay draws into its own targets in the middle of the runner's frame. This scope saves
// the GL state those draws change and puts it back, so the next pass (and ImGui's renderer, which
// draws into whatever framebuffer the runner bound) finds GL as it was.
#include "gl/gl.hpp"

namespace fx {

class GlStateScope {
public:
    GlStateScope();
    ~GlStateScope();
    GlStateScope(const GlStateScope&) = delete;
    GlStateScope& operator=(const GlStateScope&) = delete;

private:
    GLint drawFramebuffer_ = 0, readFramebuffer_ = 0, viewport_[4] = {0, 0, 0, 0};
    GLint program_ = 0, vertexArray_ = 0, activeTexture_ = 0, texture0_ = 0, sampler0_ = 0;
    GLint packAlignment_ = 4, unpackAlignment_ = 4;
    GLboolean colorMask_[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
    bool blend_ = false, depthTest_ = false, cullFace_ = false, scissorTest_ = false, stencilTest_ = false;
    bool framebufferSrgb_ = false;
};

// The state the overlay's own full-screen draws want (inside a GlStateScope): no blending, depth,
// culling, scissor, stencil or sRGB encoding, all colour channels written.
void usePlainDrawState();

}  // namespace fx
