#pragma once
// The texture pool's allocator on GL: immutable-storage 2D textures, labelled with the resource's
// name so debuggers and KHR_debug messages say "bloom.down[3]", not "texture 17".
#include <map>

#include "gl/texture.hpp"
#include "render/texture_allocator.hpp"
#include "render/texture_desc.hpp"

namespace fx {

class GlTextureAllocator final : public TextureAllocator {
public:
    NativeTexture create(const TextureSpec& spec, std::string_view label) override;
    void destroy(NativeTexture texture) override;
    void relabel(NativeTexture texture, std::string_view label) override;

    // How many textures were deleted so far. GL may give a deleted texture's name to a new one, so
    // whoever caches objects by texture name (framebuffers) drops them when this changes.
    std::uint64_t destroyedCount() const { return destroyed_; }

private:
    std::map<NativeTexture, gl::Texture> textures_;
    std::uint64_t destroyed_ = 0;
};

}  // namespace fx
