#pragma once
// Reading textures back as exact floats: captures, the inspector's pixel probe, and every test
// that checks numbers read the GPU's values through here.
#include "gl/texture.hpp"
#include "image/image.hpp"

namespace fx::gl {

// The whole level as floats (depth textures as one channel, colour as the format's channels:
// readbackChannelCount in gl/gl_formats.hpp).
FloatImage readTexture(const Texture& texture, int level = 0);
FloatImage readTexture(GLuint texture, const TextureSpec& spec, int level = 0);

// One texel of a level, all four channels (missing channels read as 0, alpha as 1).
struct Texel {
    float value[4] = {0, 0, 0, 1};
};
Texel readTexel(GLuint texture, const TextureSpec& spec, int level, int x, int y);

// The colour attachment 0 of a framebuffer (0 = the window's back buffer) as 8-bit RGBA.
ByteImage readFramebufferRgba8(GLuint framebuffer, int width, int height);

}  // namespace fx::gl
