#pragma once
// fxlab's texture formats (base/texture_format.hpp, where every other fact about them lives) as GL
// internal formats, and how a readback transfers one.
#include "base/texture_format.hpp"
#include "gl/gl.hpp"

namespace fx {

GLenum glInternalFormat(TextureFormat format);

// Channels a float readback of the format delivers: the colour channels, or the depth alone (a
// depth-stencil texture reads back as depth).
int readbackChannelCount(TextureFormat format);
// The pixel transfer format of that readback (GL_RED ... GL_RGBA, or GL_DEPTH_COMPONENT).
GLenum readbackPixelFormat(TextureFormat format);

}  // namespace fx
