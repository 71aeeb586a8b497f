#include "effects/deferred/point_light_buffer.hpp"

#include <algorithm>

#include "scene/scene_light_grid.hpp"
#include "scene/scene_limits.hpp"

namespace fx {

// The light list grows with the scene: at most its explicit lights and its grids' lights, bounded by the
// scene's limits, and far below the 16 MiB storage block every GL 4.5 device allows (docs/reliability.md).
static_assert((scene_limits::kMaxLights + std::size_t(kMaxGridLights)) * sizeof(GpuPointLight) <=
                  (std::size_t(1) << 24),
              "the scene's lights must fit GL 4.5's minimum shader storage block");

std::vector<GpuPointLight> gpuPointLights(const std::vector<Light>& lights, int maxCount, glm::vec3 offset) {
    std::vector<GpuPointLight> out;
    for (const Light& light : lights) {
        if (int(out.size()) >= maxCount) break;
        if (light.type != LightType::point) continue;
        out.push_back({glm::vec4(light.position + offset, light.radius),
                       glm::vec4(light.color * light.intensity, 0.0f)});
    }
    return out;
}

void PointLightBuffer::upload(const std::vector<GpuPointLight>& lights) {
    count_ = int(lights.size());
    // A buffer of size 0 cannot be bound: keep room for one light even when there is none.
    std::size_t bytes = std::max<std::size_t>(lights.size(), 1) * sizeof(GpuPointLight);
    if (bytes > capacity_) {
        glNamedBufferData(buffer_.name(), GLsizeiptr(bytes), nullptr, GL_DYNAMIC_DRAW);
        capacity_ = bytes;
    }
    if (!lights.empty()) glNamedBufferSubData(buffer_.name(), 0, GLsizeiptr(bytes), lights.data());
}

void PointLightBuffer::bind() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, glsl::kPointLightsBinding, buffer_.name());
}

}  // namespace fx
