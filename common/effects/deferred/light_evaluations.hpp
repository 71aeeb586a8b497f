#pragma once
// How often a frame evaluates the point-light formula (Deferred rendering chapter, hard case 20: many
// lights). Without culling every pixel evaluates every light: W x H x N, whether N full-screen passes
// each blend one light into the target (the slides' way to add lights, which also reads and writes the
// target N times, and saturates in RGBA8) or one pass loops over all N. After tiled culling a pixel
// evaluates only its tile's list.
#include <cstdint>
#include <vector>

#include "base/size2d.hpp"

namespace fx {

// W x H x N (0 for an empty output or no lights).
std::int64_t naiveLightEvaluations(Size2D size, int lights);

// The sum over the tiles of kTileSize x kTileSize pixels (partial at the right and top edges) of the
// tile's pixels times its light count. `lightsPerTile` is "cull.heat" read back: tileCount(size)
// texels, row by row from the bottom.
std::int64_t tiledLightEvaluations(Size2D size, const std::vector<float>& lightsPerTile);

}  // namespace fx
