#pragma once
// How a lesson describes a texture (a size rule, a format, a mip count) and the concrete texture it
// resolves to for one frame. Sizes are ints like the rest of fxlab's GL-facing code; negative input
// is treated as zero.
#include <cstdint>
#include <string>

#include "render/texture_format.hpp"

namespace fx {

// A width and height in texels (the output's size, a texture's size). The platform layer has its own
// Extent; this one lives here so the render layer needs nothing but base.
struct Size2D {
    int width = 0;
    int height = 0;
    bool empty() const { return width <= 0 || height <= 0; }
    bool operator==(const Size2D&) const = default;
};

// A texture's size: either absolute texels, or a fraction num/den of the output's size.
// Rounding rule for fractions: floor(output * num / den) on each axis, but never below 1 when that
// output axis is non-zero. Flooring is GL's own mip rule, so 1/2^k of the output has exactly the
// size of mip level k of an output-sized texture (1/4 of 1279x719 is 319x179). A 0x0 output gives
// 0x0 (the runner skips such frames; nothing divides by the output size).
class TextureSize {
public:
    static TextureSize absolute(int width, int height) { return TextureSize(false, width, height); }
    static TextureSize output() { return outputFraction(1, 1); }
    static TextureSize outputFraction(int numerator, int denominator) {
        return TextureSize(true, numerator, denominator);
    }

    bool relativeToOutput() const { return relative_; }
    // For absolute sizes: width and height. For fractions: numerator and denominator.
    int first() const { return a_; }
    int second() const { return b_; }

    // 0x0 for a zero denominator (the graph reports that as an error instead of dividing).
    Size2D resolve(Size2D outputSize) const;

    bool operator==(const TextureSize&) const = default;

private:
    TextureSize(bool relative, int a, int b) : relative_(relative), a_(a), b_(b) {}
    bool relative_;
    int a_;
    int b_;
};

// Asks for every level down to 1x1; the count depends on the resolved size.
inline constexpr int kFullMipChain = 0;

// What a lesson declares. mipLevels above the full chain length is clamped to it, so a chain
// declared for 1280x720 still works in a 1x1 window.
struct TextureDesc {
    TextureSize size = TextureSize::output();
    TextureFormat format = TextureFormat::RGBA8;
    int mipLevels = 1;
};

// The concrete texture: what the pool allocates and keys on, and what the GL layer creates.
struct TextureSpec {
    int width = 0;
    int height = 0;
    TextureFormat format = TextureFormat::RGBA8;
    int mipLevels = 1;
    bool operator==(const TextureSpec&) const = default;
};

// Number of levels from width x height down to 1x1: floor(log2(max(w, h))) + 1. A 0x0 size counts
// one level, so level arithmetic never goes below zero.
int fullMipChainLength(int width, int height);
// Size of one axis at a mip level: max(1, size >> level), GL's rule (0 stays 0).
int mipLevelSize(int size, int level);

TextureSpec resolve(const TextureDesc& desc, Size2D outputSize);

// Bytes of all mip levels.
std::uint64_t textureBytes(const TextureSpec& spec);

std::string toString(Size2D size);              // "1279x719"
std::string toString(const TextureSize& size);  // "1/4 output", "output", "2048x2048"
std::string toString(const TextureSpec& spec);  // "319x179 RGBA16F, 9 mips"

}  // namespace fx
