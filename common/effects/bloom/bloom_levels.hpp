#pragma once
// The sizes of a bloom chain, and how wide each of its levels blurs: GL-free maths the effect, the
// lesson's panel and the tests share.
//
// A chain starts at 1/firstDivisor of the output (Shader effects: a quarter, Bloom: a half) and halves
// with integer division from level to level, GL's mip rule: level k is output / (firstDivisor * 2^k),
// floored on each axis. A level that would be narrower or lower than one texel is not created, so a
// small window gets a shorter chain instead of a zero-sized texture (an incomplete framebuffer, and a
// texel size of 1/0 in the shaders: Bloom chapter, hard case 7). A 0x0 output has no levels at all.
#include <vector>

#include "render/texture_desc.hpp"

namespace fx {

inline constexpr int kBloomMaxLevels = 8;

struct BloomLevel {
    int index = 0;    // 0: the largest level
    int divisor = 1;  // the level is the output's size / divisor (TextureSize::outputFraction(1, divisor))
    Size2D size{};
};

// The levels of a chain of at most `requested` levels (clamped to 1..kBloomMaxLevels) that exist for
// `output`: every one is at least 1x1 by flooring alone, never by clamping.
std::vector<BloomLevel> bloomLevels(Size2D output, int firstDivisor, int requested);

// The variance (in source texels squared, per axis) of one pass's filter at an exact 2:1 ratio,
// including what bilinear filtering adds (a tap a fraction f between texel centres adds f(1 - f)).
//   downsample: four diagonal taps at +-offset from the destination centre (a source texel corner);
//   upsample: four axial taps at +-2 offset (weight 1) and four diagonal at +-offset (weight 2), /12,
//             the destination centre a quarter texel from a source centre (Bloom chapter, §1.6).
double bloomDownsampleVariance(double offset);
double bloomUpsampleVariance(double offset);

// The width (standard deviation, in output pixels) of the glow that level `level` of a seed-001
// chain contributes: its light went down through the bright pass and `level` downsamples, then up
// through `level` upsamples and the composite's. The reference glow sums Gaussians of these widths,
// so it has the chain's radius level by level.
double bloomLevelSigma(int level, double downOffset, double upOffset);

}  // namespace fx
