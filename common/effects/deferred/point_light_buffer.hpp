#pragma once
// The point lights the deferred passes read, in a storage buffer at binding glsl::kPointLightsBinding
// (shaders/effects/deferred/point_lights.glsl): per light its world position and radius, and its
// colour times intensity. Directional and spot lights are not in it (the sun is lit with its shadow
// separately; spot lights are not part of this lesson).
#include <vector>

#include <glm/vec4.hpp>

#include "effects/deferred/deferred_bindings.hpp"
#include "gl/object.hpp"
#include "scene/scene_light.hpp"

namespace fx {

struct GpuPointLight {
    glm::vec4 positionRadius;
    glm::vec4 color;  // rgb: colour x intensity; a unused
};
static_assert(sizeof(GpuPointLight) == 32, "std430 layout of PointLight");

// The point lights of `lights`, the first `maxCount` of them, moved by `offset` (the lesson can move the
// whole world away from the origin).
std::vector<GpuPointLight> gpuPointLights(const std::vector<Light>& lights, int maxCount,
                                          glm::vec3 offset = glm::vec3(0.0f));

class PointLightBuffer {
public:
    // Replaces the buffer's content (it grows when needed).
    void upload(const std::vector<GpuPointLight>& lights);
    void bind() const;  // to binding 5
    int count() const { return count_; }
    GLuint name() const { return buffer_.name(); }

private:
    gl::BufferName buffer_ = gl::createBuffer("deferred.point_lights");
    int count_ = 0;
    std::size_t capacity_ = 0;
};

}  // namespace fx
