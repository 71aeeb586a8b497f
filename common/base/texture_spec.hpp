#pragma once
// A concrete 2D texture (size, format, mip levels) and GL's mip arithmetic. The frame graph's pool
// keys on it, gl::Texture is created from it, and the inspector and readback read it; a lesson
// declares a TextureDesc (render/texture_desc.hpp) that resolves to one.
#include <cstdint>
#include <string>

#include "base/size2d.hpp"
#include "base/texture_format.hpp"

namespace fx {

struct TextureSpec {
    int width = 0;
    int height = 0;
    TextureFormat format = TextureFormat::RGBA8;
    int mipLevels = 1;

    Size2D size() const { return {width, height}; }
    // The size of one mip level (GL's rule, see mipLevelSize).
    Size2D levelSize(int level) const;
    bool operator==(const TextureSpec&) const = default;
};

// Number of levels from width x height down to 1x1: floor(log2(max(w, h))) + 1. A 0x0 size counts
// one level, so level arithmetic never goes below zero.
int fullMipChainLength(int width, int height);
// Size of one axis at a mip level: max(1, size >> level), GL's rule (0 stays 0).
int mipLevelSize(int size, int level);

// Bytes of all mip levels.
std::uint64_t textureBytes(const TextureSpec& spec);

std::string toString(const TextureSpec& spec);  // "319x179 RGBA16F, 9 mips"

}  // namespace fx
