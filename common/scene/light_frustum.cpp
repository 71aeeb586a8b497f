#include "scene/light_frustum.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace fx {
namespace {

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Some depth beyond the boxes on both sides, so geometry that touches the bounds is not clipped by
// rounding.
constexpr float kDepthMargin = 0.5f;

}  // namespace

void Bounds::add(const glm::vec3& p) {
    if (!finite(p)) return;  // one NaN vertex must not turn the whole frustum into NaN
    min = glm::min(min, p);
    max = glm::max(max, p);
}

void Bounds::add(const Bounds& b) {
    if (b.empty()) return;
    add(b.min);
    add(b.max);
}

Bounds Bounds::transformed(const glm::mat4& transform) const {
    Bounds out;
    if (empty()) return out;
    for (int i = 0; i < 8; ++i) {
        glm::vec3 corner((i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z);
        glm::vec4 p = transform * glm::vec4(corner, 1.0f);
        if (std::abs(p.w) > 1e-12f) out.add(glm::vec3(p) / p.w);
    }
    return out;
}

glm::vec3 stableUpAxis(const glm::vec3& direction) {
    // cos(8 degrees) = 0.990: closer than that to +-Y, the cross product with Y gets too short.
    return std::abs(direction.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
}

LightView fitLightFrustum(const Bounds& bounds, glm::vec3 lightDirection, float maxHalfWidth, int mapSize) {
    return fitLightFrustum(bounds, bounds, lightDirection, maxHalfWidth, mapSize);
}

LightView fitLightFrustum(const Bounds& casters, const Bounds& receivers, glm::vec3 lightDirection,
                          float maxHalfWidth, int mapSize) {
    LightView light;
    float length = glm::length(lightDirection);
    if (!(length > 1e-6f) || !std::isfinite(length)) {
        lightDirection = glm::vec3(0.0f, -1.0f, 0.0f);
        length = 1.0f;
        light.fallbackDirection = true;
    }
    glm::vec3 travel = lightDirection / length;
    light.directionToLight = -travel;

    Bounds bounds = casters;
    if (bounds.empty()) {
        bounds.add(glm::vec3(-0.5f));
        bounds.add(glm::vec3(0.5f));
    }
    Bounds depthBounds = bounds;
    depthBounds.add(receivers);
    mapSize = std::max(mapSize, 1);

    // Lateral size: the bounding sphere's radius covers the box from every direction, so the map
    // does not change size while the light turns.
    float radius = std::max(0.5f * glm::length(bounds.max - bounds.min), 1e-3f);
    float halfWidth =
        (maxHalfWidth > 0.0f && std::isfinite(maxHalfWidth)) ? std::min(radius, maxHalfWidth) : radius;
    light.halfWidth = halfWidth;
    light.texelWorldSize = 2.0f * halfWidth / float(mapSize);

    // The light's basis: looking along `travel` from the bounds' centre.
    glm::vec3 up = stableUpAxis(travel);
    glm::vec3 right = glm::normalize(glm::cross(travel, up));
    glm::vec3 trueUp = glm::cross(right, travel);

    // Snap the centre to whole texels across the light's view (not along it: depth needs no grid).
    glm::vec3 centre = bounds.centre();
    float t = light.texelWorldSize;
    float x = std::floor(glm::dot(centre, right) / t) * t;
    float y = std::floor(glm::dot(centre, trueUp) / t) * t;
    float along = glm::dot(centre, travel);
    centre = right * x + trueUp * y + travel * along;
    light.centre = centre;

    // Depth range: every corner of casters and receivers, measured along the light from the centre.
    float nearest = 1e30f, farthest = -1e30f;
    for (int i = 0; i < 8; ++i) {
        const Bounds& b = depthBounds;
        glm::vec3 corner((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                         (i & 4) ? b.max.z : b.min.z);
        float d = glm::dot(corner - centre, travel);
        nearest = std::min(nearest, d);
        farthest = std::max(farthest, d);
    }
    nearest -= kDepthMargin;
    farthest += kDepthMargin;
    light.nearDistance = nearest;
    light.farDistance = farthest;

    light.view = glm::lookAt(centre, centre + travel, trueUp);
    light.projection = glm::ortho(-halfWidth, halfWidth, -halfWidth, halfWidth, nearest, farthest);
    light.viewProjection = light.projection * light.view;
    return light;
}

}  // namespace fx
