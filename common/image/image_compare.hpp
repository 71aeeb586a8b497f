#pragma once
// How far one image is from another: the error half of "accuracy against time", and the measure
// golden-image tests hold against a tolerance.
//
// Differences are taken per channel value. For float images:
//   - both values finite                      -> |a - b|
//   - the same infinity on both sides         -> 0 (the values are equal)
//   - a NaN on either side (even on both), or an infinity the other side does not share
//                                             -> an unbounded difference, counted in nonFiniteTexels
// An unbounded difference makes rmse and maxAbs +inf and psnr -inf, so a NaN can never leave the
// RMSE looking fine (NaN arithmetic would, as every comparison with NaN is false), and the count
// says how many texels did it. Byte images have no such values.
#include <cstdint>

#include "base/result.hpp"
#include "image/image.hpp"

namespace fx {

struct ImageDifference {
    double rmse = 0.0;    // over every channel value of every texel, in the image's own units
    double psnr = 0.0;    // dB, peak 1.0 for float images and 255 for byte images; +inf when identical
    double maxAbs = 0.0;  // the largest single channel difference
    std::int64_t differingTexels = 0;  // texels with at least one differing channel
    std::int64_t nonFiniteTexels = 0;  // texels whose difference is unbounded (float images only)
};

// Fails when the shapes differ (the message names both).
Result<ImageDifference> compare(const FloatImage& a, const FloatImage& b);
Result<ImageDifference> compare(const ByteImage& a, const ByteImage& b);

// A picture of where two byte images differ, for a person: the expected image dimmed to dark grey,
// with every differing texel drawn in red that brightens with the size of the difference (even a
// difference of 1 stands out). RGBA, bottom-up, the shape of `expected`. The shapes must match.
Result<ByteImage> differenceImage(const ByteImage& expected, const ByteImage& actual);

}  // namespace fx
