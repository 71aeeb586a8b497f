#pragma once
// How a lesson describes a texture (a size rule, a format, a mip count), resolved each frame to the
// concrete TextureSpec (base/texture_spec.hpp). Sizes are ints like the rest of fxlab's GL-facing
// code; negative input is treated as zero.
#include <string>

#include "base/size2d.hpp"
#include "base/texture_spec.hpp"

namespace fx {

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

// The concrete texture for this frame's output size: what the pool allocates and keys on.
TextureSpec resolve(const TextureDesc& desc, Size2D outputSize);

std::string toString(const TextureSize& size);  // "1/4 output", "output", "2048x2048"

}  // namespace fx
