#pragma once
// Lights in a scene file. Colours are linear and may exceed 1 (HDR); intensity scales the colour.
#include <string>

#include <glm/vec3.hpp>

namespace fx {

enum class LightType { directional, point, spot };

// Shadow-map settings; only directional lights cast shadows in fxlab.
struct ShadowSettings {
    bool casts = false;
    int mapSize = 2048;         // texels per side, a power of two
    float bias = 0.0005f;       // constant depth bias, in depth-buffer units [0, 1]
    float normalOffset = 1.0f;  // offset along the surface normal, in shadow-map texels
    int filterTaps = 16;        // percentage-closer filter taps; 1 is a hard edge
    float extent = 30.0f;       // half-width (m) of the orthographic shadow frustum

    bool operator==(const ShadowSettings&) const = default;
};

struct Light {
    std::string name;
    LightType type = LightType::directional;
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // directional, spot: where the light travels (any length but 0)
    glm::vec3 position{0.0f};                // point, spot
    float radius = 10.0f;                    // point, spot: distance (m) at which the light fades to zero
    float innerConeDegrees = 20.0f;          // spot: half-angle of full brightness
    float outerConeDegrees = 30.0f;          // spot: half-angle where the light reaches zero
    ShadowSettings shadow;                   // directional

    bool castsShadows() const { return type == LightType::directional && shadow.casts; }
    bool operator==(const Light&) const = default;
};

}  // namespace fx
