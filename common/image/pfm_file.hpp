#pragma once
// Portable Float Map files: the exact-float format for captures, read by most HDR viewers.
//
// A PFM stores the float bit patterns unchanged (NaN payloads, infinities, negative values and
// denormals survive a round trip), which is what a hard-case test needs when a PNG would clamp.
// Layout: "PF\n" (RGB) or "Pf\n" (grey), "<width> <height>\n", "-1.0\n" (a negative scale means
// little-endian), then the rows bottom-to-top, which is our storage order, so rows are not flipped.
//
// PFM has no 2- or 4-channel variant. writePfm therefore writes:
//   1 channel   -> "Pf"
//   2 channels  -> "PF" as (r, g, 0)
//   3 channels  -> "PF"
//   4 channels  -> "PF" with the alpha channel DROPPED (keep alpha in a separate 1-channel capture
//                  if a test needs it)
#include <filesystem>

#include "base/result.hpp"
#include "image/image.hpp"

namespace fx {

// Written atomically: complete, or not there at all.
Status writePfm(const std::filesystem::path& path, const FloatImage& image);

// Returns 1 channel for "Pf" and 3 for "PF"; reads both byte orders.
Result<FloatImage> readPfm(const std::filesystem::path& path);

}  // namespace fx
