#pragma once
// A 2D texture with immutable storage, and what the inspector, captures and tests need to know
// about it: size, mip levels, internal format, label.
#include <string>
#include <string_view>

#include "gl/object.hpp"

namespace fx::gl {

struct TextureInfo {
    int width = 0;
    int height = 0;
    int levels = 1;
    GLenum internalFormat = GL_RGBA8;
    std::string label;
};

class Texture {
public:
    Texture() = default;
    // Immutable storage (glTextureStorage2D); sizes are clamped to at least 1x1.
    static Texture create2D(GLenum internalFormat, int width, int height, int levels, std::string_view label);

    GLuint name() const { return name_.name(); }
    explicit operator bool() const { return static_cast<bool>(name_); }
    const TextureInfo& info() const { return info_; }
    int width() const { return info_.width; }
    int height() const { return info_.height; }
    void relabel(std::string_view label);

private:
    TextureName name_;
    TextureInfo info_;
};

// Facts about internal formats that the GL layer needs (the format names are GL's).
bool isDepthFormat(GLenum internalFormat);
bool isFloatFormat(GLenum internalFormat);
int channelCount(GLenum internalFormat);
int bytesPerTexel(GLenum internalFormat);
std::string_view formatName(GLenum internalFormat);

// Size of mip level `level` of a `size`-texel dimension (never below 1).
int mipSize(int size, int level);

}  // namespace fx::gl
