#pragma once
// The one seam between the texture pool and real textures. The GL layer implements it with
// immutable-storage textures; unit tests use a fake that records the calls.
#include <cstdint>
#include <string_view>

#include "render/texture_desc.hpp"

namespace fx {

// A texture as the API knows it: a GL texture name. 0 means "no texture" (and, for the presented
// output, the window's default framebuffer).
using NativeTexture = std::uint32_t;

class TextureAllocator {
public:
    virtual ~TextureAllocator() = default;
    // A texture of exactly spec's size, format and levels, labelled for debuggers. 0 on failure.
    virtual NativeTexture create(const TextureSpec& spec, std::string_view label) = 0;
    virtual void destroy(NativeTexture texture) = 0;
    // A pooled texture reused for another resource takes that resource's name.
    virtual void relabel(NativeTexture texture, std::string_view label) = 0;
};

}  // namespace fx
