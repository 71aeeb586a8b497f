#include "scene/scene_light_grid.hpp"

#include <algorithm>
#include <cstdint>

#include "base/log.hpp"

namespace fx {
namespace {

// A 32-bit integer hash (the "lowbias32" mix): spreads neighbouring indices over the whole range.
std::uint32_t hash32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

// A fully saturated hue at h in [0, 1): the colour wheel's six segments.
glm::vec3 hueColor(float h) {
    float r = std::clamp(std::abs(h * 6.0f - 3.0f) - 1.0f, 0.0f, 1.0f);
    float g = std::clamp(2.0f - std::abs(h * 6.0f - 2.0f), 0.0f, 1.0f);
    float b = std::clamp(2.0f - std::abs(h * 6.0f - 4.0f), 0.0f, 1.0f);
    return {r, g, b};
}

}  // namespace

glm::vec3 gridLightColor(int index, int seed, float saturation) {
    std::uint32_t h =
        hash32(static_cast<std::uint32_t>(index) * 0x9e3779b9u ^ hash32(static_cast<std::uint32_t>(seed)));
    float hue = float(h >> 8) / float(1u << 24);
    float s = std::clamp(saturation, 0.0f, 1.0f);
    return glm::vec3(1.0f - s) + s * hueColor(hue);
}

std::vector<Light> expandLightGrid(const LightGrid& grid) {
    std::vector<Light> lights;
    const int nx = std::max(grid.count.x, 1), nz = std::max(grid.count.y, 1);
    lights.reserve(static_cast<std::size_t>(nx) * static_cast<std::size_t>(nz));
    // Centred on the grid's centre: the first light sits half the grid's extent to the -X, -Z side.
    const glm::vec2 origin = -0.5f * glm::vec2(float(nx - 1), float(nz - 1)) * grid.spacing;
    for (int z = 0; z < nz; ++z) {
        for (int x = 0; x < nx; ++x) {
            int index = z * nx + x;
            Light light;
            light.type = LightType::point;
            light.name = cat(grid.name.empty() ? "grid" : grid.name, "[", index, "]");
            light.position = grid.center + glm::vec3(origin.x + float(x) * grid.spacing.x, 0.0f,
                                                     origin.y + float(z) * grid.spacing.y);
            light.color = gridLightColor(index, grid.seed, grid.saturation);
            light.intensity = grid.intensity;
            light.radius = grid.radius;
            lights.push_back(light);
        }
    }
    return lights;
}

}  // namespace fx
