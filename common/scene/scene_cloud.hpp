#pragma once
// Cloud layers: a horizontal slab of ray-marched density between two heights, read from a tiling
// density texture at two scales that scroll at their own speeds.
#include <array>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/asset_ref.hpp"

namespace fx {

struct CloudNoise {
    float scale = 0.05f;     // texture repeats per metre
    glm::vec2 scroll{0.0f};  // texture units per second (the offset is wrapped, so it stays small)

    bool operator==(const CloudNoise&) const = default;
};

struct CloudLayer {
    std::string name;
    float bottom = 0.0f;  // world height (m) of the slab's lower face
    float top = 2.0f;     // upper face; always above bottom
    AssetRef densityTexture;
    std::array<CloudNoise, 2> noise{CloudNoise{0.05f, {-0.0019f, -0.0041f}},
                                    CloudNoise{0.11f, {-0.0027f, -0.0013f}}};
    float threshold = 0.5f;  // density at or below this is clear sky; in [0, 1) because 1/(1 - threshold)
    int steps = 8;           // ray-march samples through the slab, [1, 512]
    glm::vec3 color{1.0f};   // linear HDR

    bool operator==(const CloudLayer&) const = default;
};

}  // namespace fx
