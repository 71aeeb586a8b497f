#include "gl/gl_formats.hpp"

namespace fx {

GLenum glInternalFormat(TextureFormat format) {
    switch (format) {
        case TextureFormat::RGBA8:
            return GL_RGBA8;
        case TextureFormat::SRGB8_ALPHA8:
            return GL_SRGB8_ALPHA8;
        case TextureFormat::RGBA16F:
            return GL_RGBA16F;
        case TextureFormat::RGBA32F:
            return GL_RGBA32F;
        case TextureFormat::R11F_G11F_B10F:
            return GL_R11F_G11F_B10F;
        case TextureFormat::RG16F:
            return GL_RG16F;
        case TextureFormat::R16F:
            return GL_R16F;
        case TextureFormat::R32F:
            return GL_R32F;
        case TextureFormat::R8:
            return GL_R8;
        case TextureFormat::RGB32F:
            return GL_RGB32F;
        case TextureFormat::Depth32F:
            return GL_DEPTH_COMPONENT32F;
        case TextureFormat::Depth24:
            return GL_DEPTH_COMPONENT24;
        case TextureFormat::Depth24Stencil8:
            return GL_DEPTH24_STENCIL8;
    }
    return GL_RGBA8;
}

int readbackChannelCount(TextureFormat format) {
    return isDepth(format) ? 1 : channelCount(format);
}

GLenum readbackPixelFormat(TextureFormat format) {
    if (isDepth(format)) return GL_DEPTH_COMPONENT;
    switch (channelCount(format)) {
        case 1:
            return GL_RED;
        case 2:
            return GL_RG;
        case 3:
            return GL_RGB;
        default:
            return GL_RGBA;
    }
}

}  // namespace fx
