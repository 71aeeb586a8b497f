#include "effects/deferred/light_evaluations.hpp"

#include <algorithm>

#include "effects/deferred/tiled_culling.hpp"

namespace fx {

std::int64_t naiveLightEvaluations(Size2D size, int lights) {
    return std::int64_t(std::max(size.width, 0)) * std::max(size.height, 0) * std::max(lights, 0);
}

std::int64_t tiledLightEvaluations(Size2D size, const std::vector<float>& lightsPerTile) {
    const Size2D tiles = tileCount(size);
    std::int64_t sum = 0;
    for (int ty = 0; ty < tiles.height; ++ty)
        for (int tx = 0; tx < tiles.width; ++tx) {
            const std::size_t i = std::size_t(ty) * std::size_t(tiles.width) + std::size_t(tx);
            if (i >= lightsPerTile.size()) return sum;
            const int w = std::clamp(size.width - tx * kTileSize, 0, kTileSize);
            const int h = std::clamp(size.height - ty * kTileSize, 0, kTileSize);
            sum += std::int64_t(w) * h * std::int64_t(std::max(lightsPerTile[i], 0.0f));
        }
    return sum;
}

}  // namespace fx
