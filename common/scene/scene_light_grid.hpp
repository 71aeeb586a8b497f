#pragma once
// Many point lights without writing each one: a "lightGrids" entry in a scene file lays out a
// rectangle of point lights, count.x by count.y, spacing apart on the horizontal plane at the
// grid's centre height. Lesson 10 lights its scene with a thousand of these (deferred shading and
// light culling). The colours come from an integer hash of the light's index and the seed, so a grid
// is the same on every machine and no fract(sin) is involved.
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/scene_light.hpp"

namespace fx {

// The most lights all of a scene's grids may make together (the GPU light list's size).
inline constexpr int kMaxGridLights = 1024;

struct LightGrid {
    std::string name;
    glm::vec3 center{0.0f, 1.0f, 0.0f};
    glm::ivec2 count{4, 4};   // lights along X and along Z, each at least 1
    glm::vec2 spacing{2.0f};  // metres between neighbours along X and along Z
    float radius = 3.0f;      // each light fades to zero at this distance (m)
    float intensity = 1.0f;   // scales every light's colour
    float saturation = 0.6f;  // 0: white lights; 1: fully saturated hues
    int seed = 1;             // picks the hues

    int lightCount() const { return count.x * count.y; }
    bool operator==(const LightGrid&) const = default;
};

// The grid's lights, row by row (X fastest), named "<grid name>[i]".
std::vector<Light> expandLightGrid(const LightGrid& grid);

// A hue for light `index` of a grid seeded `seed`: an RGB colour with its largest channel 1,
// `saturation` of the way from white to the pure hue.
glm::vec3 gridLightColor(int index, int seed, float saturation);

}  // namespace fx
