#include "scene/scene_camera.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace fx {

glm::vec3 viewDirection(const Camera& camera) {
    if (camera.aim == CameraAim::target) {
        glm::vec3 view = camera.target - camera.position;
        float length = glm::length(view);
        // The loader refuses a target on the camera; a scene built in code might still have one.
        return length > 0.0f ? view / length : glm::vec3(0.0f, 0.0f, -1.0f);
    }
    float yaw = glm::radians(camera.yawDegrees);
    float pitch = glm::radians(camera.pitchDegrees);
    return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

float horizontalFovDegrees(const Lens& lens) {
    return glm::degrees(2.0f * std::atan(lens.sensorWidthMm / (2.0f * lens.focalLengthMm)));
}

float verticalFovDegrees(const Camera& camera, float aspect) {
    if (!camera.lens) return camera.fovYDegrees;
    if (!(aspect > 0.0f) || !std::isfinite(aspect)) aspect = 1.0f;
    float sensorHeightMm = camera.lens->sensorWidthMm / aspect;
    return glm::degrees(2.0f * std::atan(sensorHeightMm / (2.0f * camera.lens->focalLengthMm)));
}

}  // namespace fx
