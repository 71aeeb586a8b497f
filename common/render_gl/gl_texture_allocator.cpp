#include "render_gl/gl_texture_allocator.hpp"

#include "base/log.hpp"

namespace fx {

NativeTexture GlTextureAllocator::create(const TextureSpec& spec, std::string_view label) {
    if (spec.width <= 0 || spec.height <= 0) return 0;
    auto texture = gl::Texture::create2D(spec.format, spec.width, spec.height, spec.mipLevels, label);
    NativeTexture name = texture.name();
    textures_.emplace(name, std::move(texture));
    return name;
}

void GlTextureAllocator::destroy(NativeTexture texture) {
    destroyed_ += textures_.erase(texture);
}

void GlTextureAllocator::relabel(NativeTexture texture, std::string_view label) {
    auto it = textures_.find(texture);
    if (it != textures_.end()) it->second.relabel(label);
}

}  // namespace fx
