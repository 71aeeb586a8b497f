#include "gl/texture.hpp"

#include <algorithm>

#include "gl/gl_formats.hpp"

namespace fx::gl {

Texture Texture::create2D(TextureFormat format, int width, int height, int levels, std::string_view label) {
    Texture t;
    t.spec_ = {std::max(width, 1), std::max(height, 1), format, std::max(levels, 1)};
    t.label_ = std::string(label);
    t.name_ = createTexture(GL_TEXTURE_2D, label);
    glTextureStorage2D(t.name(), t.spec_.mipLevels, glInternalFormat(format), t.spec_.width, t.spec_.height);
    // Sample what was written: no mip filtering unless the texture has the levels for it.
    glTextureParameteri(t.name(), GL_TEXTURE_MIN_FILTER,
                        t.spec_.mipLevels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTextureParameteri(t.name(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t.name(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.name(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

void Texture::relabel(std::string_view label) {
    label_ = std::string(label);
    name_.label(label);
}

}  // namespace fx::gl
