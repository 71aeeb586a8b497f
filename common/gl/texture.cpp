#include "gl/texture.hpp"

#include <algorithm>

namespace fx::gl {

Texture Texture::create2D(GLenum internalFormat, int width, int height, int levels, std::string_view label) {
    Texture t;
    t.info_ = {std::max(width, 1), std::max(height, 1), std::max(levels, 1), internalFormat, std::string(label)};
    t.name_ = createTexture(GL_TEXTURE_2D, label);
    glTextureStorage2D(t.name(), t.info_.levels, internalFormat, t.info_.width, t.info_.height);
    // Sample what was written: no mip filtering unless the texture has the levels for it.
    glTextureParameteri(t.name(), GL_TEXTURE_MIN_FILTER, t.info_.levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTextureParameteri(t.name(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t.name(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.name(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

void Texture::relabel(std::string_view label) {
    info_.label = std::string(label);
    name_.label(label);
}

bool isDepthFormat(GLenum f) {
    switch (f) {
        case GL_DEPTH_COMPONENT16:
        case GL_DEPTH_COMPONENT24:
        case GL_DEPTH_COMPONENT32:
        case GL_DEPTH_COMPONENT32F:
        case GL_DEPTH24_STENCIL8:
        case GL_DEPTH32F_STENCIL8: return true;
        default: return false;
    }
}

bool isFloatFormat(GLenum f) {
    switch (f) {
        case GL_R16F: case GL_RG16F: case GL_RGB16F: case GL_RGBA16F:
        case GL_R32F: case GL_RG32F: case GL_RGB32F: case GL_RGBA32F:
        case GL_R11F_G11F_B10F: case GL_DEPTH_COMPONENT32F: return true;
        default: return false;
    }
}

int channelCount(GLenum f) {
    switch (f) {
        case GL_R8: case GL_R16F: case GL_R32F: return 1;
        case GL_RG8: case GL_RG16F: case GL_RG32F: return 2;
        case GL_RGB8: case GL_SRGB8: case GL_RGB16F: case GL_RGB32F: case GL_R11F_G11F_B10F: return 3;
        default: return isDepthFormat(f) ? 1 : 4;
    }
}

int bytesPerTexel(GLenum f) {
    switch (f) {
        case GL_R8: return 1;
        case GL_RG8: case GL_R16F: case GL_DEPTH_COMPONENT16: return 2;
        case GL_RGB8: case GL_SRGB8: return 3;
        case GL_RGBA8: case GL_SRGB8_ALPHA8: case GL_RG16F: case GL_R32F: case GL_R11F_G11F_B10F:
        case GL_DEPTH_COMPONENT24: case GL_DEPTH_COMPONENT32: case GL_DEPTH_COMPONENT32F: case GL_DEPTH24_STENCIL8: return 4;
        case GL_RGB16F: return 6;
        case GL_RGBA16F: case GL_RG32F: case GL_DEPTH32F_STENCIL8: return 8;
        case GL_RGB32F: return 12;
        case GL_RGBA32F: return 16;
        default: return 4;
    }
}

std::string_view formatName(GLenum f) {
    switch (f) {
        case GL_R8: return "R8";
        case GL_RG8: return "RG8";
        case GL_RGB8: return "RGB8";
        case GL_RGBA8: return "RGBA8";
        case GL_SRGB8: return "SRGB8";
        case GL_SRGB8_ALPHA8: return "SRGB8_ALPHA8";
        case GL_R16F: return "R16F";
        case GL_RG16F: return "RG16F";
        case GL_RGB16F: return "RGB16F";
        case GL_RGBA16F: return "RGBA16F";
        case GL_R32F: return "R32F";
        case GL_RG32F: return "RG32F";
        case GL_RGB32F: return "RGB32F";
        case GL_RGBA32F: return "RGBA32F";
        case GL_R11F_G11F_B10F: return "R11F_G11F_B10F";
        case GL_DEPTH_COMPONENT16: return "DEPTH16";
        case GL_DEPTH_COMPONENT24: return "DEPTH24";
        case GL_DEPTH_COMPONENT32: return "DEPTH32";
        case GL_DEPTH_COMPONENT32F: return "DEPTH32F";
        case GL_DEPTH24_STENCIL8: return "DEPTH24_STENCIL8";
        case GL_DEPTH32F_STENCIL8: return "DEPTH32F_STENCIL8";
        default: return "unknown format";
    }
}

int mipSize(int size, int level) { return std::max(1, size >> level); }

}  // namespace fx::gl
