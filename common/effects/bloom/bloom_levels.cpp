#include "effects/bloom/bloom_levels.hpp"

#include <algorithm>
#include <cmath>

namespace fx {
namespace {

// What bilinear filtering adds to a tap `position` texels from a texel centre: f(1 - f).
double bilinearVariance(double position) {
    double f = position - std::floor(position);
    return f * (1.0 - f);
}

}  // namespace

std::vector<BloomLevel> bloomLevels(Size2D output, int firstDivisor, int requested) {
    std::vector<BloomLevel> levels;
    if (output.empty() || firstDivisor < 1) return levels;
    int count = std::clamp(requested, 1, kBloomMaxLevels);
    long long divisor = firstDivisor;
    for (int k = 0; k < count; ++k, divisor *= 2) {
        Size2D size{int(output.width / divisor), int(output.height / divisor)};
        if (size.empty()) break;  // below one texel: this level and every smaller one are not made
        levels.push_back({k, int(divisor), size});
    }
    return levels;
}

double bloomDownsampleVariance(double offset) {
    // The destination centre is a source texel corner, half a texel from the centres either side.
    return offset * offset + bilinearVariance(0.5 + offset);
}

double bloomUpsampleVariance(double offset) {
    // Per axis: the two axial taps on this axis at +-2 offset (weight 1 each), the two on the other
    // axis at 0 (weight 1 each), and four diagonal taps at +-offset (weight 2 each); the destination
    // centre is a quarter texel from a source centre (the other phase is its mirror image).
    struct Tap {
        double position, weight;
    };
    const Tap taps[] = {{-2 * offset, 1}, {2 * offset, 1}, {0, 1},      {0, 1},
                        {-offset, 2},     {-offset, 2},    {offset, 2}, {offset, 2}};
    double spread = 0, filtering = 0;
    for (const Tap& t : taps) {
        spread += t.weight * t.position * t.position;
        filtering += t.weight * bilinearVariance(0.25 + t.position);
    }
    return (spread + filtering) / 12.0;
}

double bloomLevelSigma(int level, double downOffset, double upOffset) {
    // Level j of a seed-001 chain has texels 2^(j+1) output pixels wide. Its light was filtered by the
    // bright pass (source texels 1 px) and the downsamples into levels 1..j (source texels 2^i px),
    // then by the upsamples out of levels j..0 (source texels 2^(i+1) px). Variances add.
    double variance = 0;
    double texel = 1;  // the source texel of the pass, in output pixels
    for (int i = 0; i <= level; ++i, texel *= 2) {
        variance += bloomDownsampleVariance(downOffset) * texel * texel;
        variance += bloomUpsampleVariance(upOffset) * (2 * texel) * (2 * texel);
    }
    return std::sqrt(variance);
}

}  // namespace fx
