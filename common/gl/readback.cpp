#include "gl/readback.hpp"

#include <algorithm>

#include "gl/gl_formats.hpp"

namespace fx::gl {

FloatImage readTexture(GLuint texture, const TextureSpec& spec, int level) {
    FloatImage image;
    image.width = mipLevelSize(spec.width, level);
    image.height = mipLevelSize(spec.height, level);
    image.channels = readbackChannelCount(spec.format);
    image.texels.assign(static_cast<std::size_t>(image.width) * image.height * image.channels, 0.0f);
    GLenum format = readbackPixelFormat(spec.format);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(texture, level, format, GL_FLOAT,
                      static_cast<GLsizei>(image.texels.size() * sizeof(float)), image.texels.data());
    return image;
}

FloatImage readTexture(const Texture& texture, int level) {
    return readTexture(texture.name(), texture.spec(), level);
}

Texel readTexel(GLuint texture, const TextureSpec& spec, int level, int x, int y) {
    Texel texel;
    Size2D size = spec.levelSize(level);
    if (x < 0 || y < 0 || x >= size.width || y >= size.height) return texel;
    int channels = readbackChannelCount(spec.format);
    GLenum format = readbackPixelFormat(spec.format);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    float values[4] = {0, 0, 0, 1};
    glGetTextureSubImage(texture, level, x, y, 0, 1, 1, 1, format, GL_FLOAT, sizeof(values), values);
    std::copy(values, values + channels, texel.value);
    return texel;
}

ByteImage readFramebufferRgba8(GLuint framebuffer, int width, int height) {
    ByteImage image;
    image.width = std::max(width, 0);
    image.height = std::max(height, 0);
    image.channels = 4;
    image.texels.assign(static_cast<std::size_t>(image.width) * image.height * 4, 0);
    if (image.texels.empty()) return image;
    GLint previous = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previous);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    if (framebuffer == 0) glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.texels.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(previous));
    return image;
}

}  // namespace fx::gl
