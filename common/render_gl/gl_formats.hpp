#pragma once
// The frame graph's texture formats as GL internal formats.
#include "gl/gl.hpp"
#include "render/texture_format.hpp"

namespace fx {

GLenum glInternalFormat(TextureFormat format);

}  // namespace fx
