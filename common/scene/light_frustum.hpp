#pragma once
// The orthographic view a directional light's shadow map is drawn with, fitted to what it must cover.
// GL-free, so the fit (and its hard cases) is unit-tested without a context.
//
//   Bounds world = ...;                                   // casters and receivers, world space
//   LightView light = fitLightFrustum(world, sun.direction, sun.shadow.extent, sun.shadow.mapSize);
//   // light.viewProjection maps world space to the shadow map's clip space ([-1, 1] on every axis).
//
// Hard cases handled here rather than in each lesson:
//  - a light direction parallel to the world's up axis (a sun straight overhead): lookAt with up = +Y
//    would divide by |dir x up| = 0 and fill the matrix with NaN, so the view's up axis is the world
//    axis least aligned with the light;
//  - a zero-length or non-finite direction: straight down, and `fallbackDirection` says so;
//  - empty or non-finite bounds: a 1 m box at the origin;
//  - casters outside the fitted depth range: the shadow vertex shaders clamp depth to the near plane
//    ("pancaking") so a caster behind the light still throws its shadow; the fit only has to cover
//    the receivers' depth.
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace fx {

struct Bounds {
    glm::vec3 min{1e30f};
    glm::vec3 max{-1e30f};

    bool empty() const { return !(min.x <= max.x && min.y <= max.y && min.z <= max.z); }
    void add(const glm::vec3& p);
    void add(const Bounds& b);
    // The box that holds this one after `transform` (all eight corners transformed).
    Bounds transformed(const glm::mat4& transform) const;
    glm::vec3 centre() const { return 0.5f * (min + max); }
};

struct LightView {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::mat4 viewProjection{1.0f};
    glm::vec3 directionToLight{0.0f, 1.0f, 0.0f};  // normalised: the Lambert term's L
    glm::vec3 centre{0.0f};                        // the point the map is centred on (snapped to texels)
    float halfWidth = 1.0f;                        // metres from the map's centre to its edge
    float nearDistance = 0.0f;                     // the depth range along the light, in metres
    float farDistance = 1.0f;
    float texelWorldSize = 1.0f;     // metres one shadow-map texel covers (2 halfWidth / mapSize)
    bool fallbackDirection = false;  // the direction given could not be used
};

// `lightDirection` is where the light travels (a scene file's `direction`). Across the light, the map
// covers the casters only: seen along a directional light a shadow lands on the texels of the caster
// that throws it, so a receiver outside the casters' footprint is lit and needs no texel (a huge
// ground plane would otherwise spread the texels thin). It never covers more than `maxHalfWidth`
// metres either side of the casters' centre; maxHalfWidth <= 0 means no limit. Along the light, the
// depth range holds casters and receivers, so no receiver falls behind the far plane.
// The centre is snapped to whole texels of a `mapSize` map so a moving caster does not make the
// shadows of still ones shimmer.
LightView fitLightFrustum(const Bounds& casters, const Bounds& receivers, glm::vec3 lightDirection,
                          float maxHalfWidth, int mapSize);
// The same with one box for both.
LightView fitLightFrustum(const Bounds& bounds, glm::vec3 lightDirection, float maxHalfWidth, int mapSize);

// The world axis to use as a view's "up" when looking along `direction`: +Y unless the direction is
// within about 8 degrees of it, then +Z.
glm::vec3 stableUpAxis(const glm::vec3& direction);

}  // namespace fx
