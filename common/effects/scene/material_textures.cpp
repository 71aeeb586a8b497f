#include "effects/scene/material_textures.hpp"

#include <algorithm>
#include <climits>
#include <cstring>

#include "base/log.hpp"
#include "gl/debug_output.hpp"
#include "gl/texture_image.hpp"

namespace fx {

GLuint MaterialTextures::upload(const std::string& key, const std::string& label, int width, int height,
                                const unsigned char* rgba) {
    gl::DebugGroup group(cat("upload ", label));  // the mip chain is GPU work a debugger should name
    gl::Texture texture = gl::Texture::create2D(TextureFormat::SRGB8_ALPHA8, width, height,
                                                fullMipChainLength(width, height), label);
    glTextureSubImage2D(texture.name(), 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glGenerateTextureMipmap(texture.name());
    glTextureParameteri(texture.name(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(texture.name(), GL_TEXTURE_WRAP_T, GL_REPEAT);
    GLuint name = texture.name();
    textures_.emplace(key, std::move(texture));
    return name;
}

GLuint MaterialTextures::white() {
    if (!white_) {
        white_ = gl::Texture::create2D(TextureFormat::SRGB8_ALPHA8, 1, 1, 1, "material.white");
        const unsigned char texel[4] = {255, 255, 255, 255};
        glTextureSubImage2D(white_.name(), 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    }
    return white_.name();
}

GLuint MaterialTextures::file(const std::filesystem::path& path) {
    std::string key = path.lexically_normal().string();
    if (auto it = textures_.find(key); it != textures_.end()) return it->second.name();
    if (std::find(failures_.begin(), failures_.end(), key) != failures_.end()) return white();
    auto image = gl::readTextureImage(path);
    if (!image) {
        log::error(image.error(), "; drawn without the texture");
        failures_.push_back(key);
        return white();
    }
    // ByteImage rows run bottom-up, which is the order GL's first row (t = 0) expects.
    return upload(key, path.filename().string(), image->width, image->height, image->texels.data());
}

GLuint MaterialTextures::encoded(const std::string& key, const std::vector<unsigned char>& bytes) {
    if (auto it = textures_.find(key); it != textures_.end()) return it->second.name();
    if (std::find(failures_.begin(), failures_.end(), key) != failures_.end()) return white();
    auto image = gl::decodeTextureImage(std::as_bytes(std::span(bytes.data(), bytes.size())), key);
    if (!image) {
        log::error(image.error(), "; drawn without the texture");
        failures_.push_back(key);
        return white();
    }
    return upload(key, key, image->width, image->height, image->texels.data());
}

std::uint64_t MaterialTextures::bytes() const {
    std::uint64_t total = 0;
    for (const auto& [key, texture] : textures_) total += textureBytes(texture.spec());
    return total;
}

}  // namespace fx
