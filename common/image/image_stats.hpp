#pragma once
// What is in a float capture, per channel: the numbers a hard-case test asserts on ("no NaN, no
// Inf, nothing negative, the maximum stays below the clamp") and the smoke tests print.
#include <cstdint>
#include <vector>

#include "image/image.hpp"

namespace fx {

struct ChannelStats {
    // min, max and mean cover the finite values only, so one NaN cannot hide the range of the rest.
    // With no finite value at all they are 0 and finiteCount says so.
    float min = 0.0f, max = 0.0f;
    double mean = 0.0;
    std::int64_t finiteCount = 0;
    std::int64_t nanCount = 0;
    std::int64_t infCount = 0;       // +Inf and -Inf
    std::int64_t negativeCount = 0;  // finite values below zero (-0.0 is not negative; -Inf is in infCount)
};

// One entry per channel.
std::vector<ChannelStats> computeStats(const FloatImage& image);

// True when every value of every texel is within `tolerance` of the first texel's. A smoke test
// uses it to reject a blank picture (cleared to one colour, nothing drawn). An empty image is flat.
bool isFlat(const ByteImage& image, int tolerance);

}  // namespace fx
