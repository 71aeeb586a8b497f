#pragma once
// How float data becomes a picture a person can look at (captures, the inspector, golden images).
//
// Both transforms first clamp each value to [0, 1], then scale to 0..255 rounding to nearest:
//   Direct        v' = round(255 * clamp(v))                 UNORM colour, masks, depth
//   LinearToSrgb  v' = round(255 * srgb(clamp(v)))           linear HDR light, the usual case
// with the exact sRGB encoding (IEC 61966-2-1), not the 1/2.2 power approximation:
//   srgb(c) = 12.92 c                      for c <= 0.0031308
//           = 1.055 c^(1/2.4) - 0.055      otherwise
// So linear 0.5 shows as 188 under LinearToSrgb and as 128 under Direct. Alpha is coverage, not
// light, so it always goes through Direct.
//
// Values that are not numbers must stay visible rather than blend in: a texel with a NaN in any
// channel becomes opaque magenta (255, 0, 255, 255). +Inf clamps to 1 like any large value and -Inf
// to 0. One channel shows as grey (r, r, r), two channels as (r, g, 0), and images without alpha
// get alpha 255. The result always has 4 channels (RGBA) and keeps the bottom-up row order.
// docs/captures.md says the same for readers of the captures.
#include <cstdint>

#include "image/image.hpp"

namespace fx {

enum class ViewTransform { Direct, LinearToSrgb };

ByteImage toDisplay(const FloatImage& image, ViewTransform transform);

// One value through the transform (exposed so the overlay can label a picked texel the same way).
std::uint8_t toDisplayValue(float value, ViewTransform transform);

// The exact sRGB encoding of a linear value already in [0, 1].
double encodeSrgb(double linear);

}  // namespace fx
