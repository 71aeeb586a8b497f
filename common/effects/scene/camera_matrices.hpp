#pragma once
// View and projection matrices for a scene camera at a framebuffer size. A 0x0 framebuffer (a
// minimised window) would give aspect = x/0; the aspect falls back to 1 so no matrix holds NaN.
#include <glm/mat4x4.hpp>

#include "scene/scene_camera.hpp"

namespace fx {

struct CameraMatrices {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::mat4 viewProjection{1.0f};
    glm::vec3 position{0.0f};
    float aspect = 1.0f;
};

CameraMatrices cameraMatrices(const Camera& camera, int width, int height);

}  // namespace fx
