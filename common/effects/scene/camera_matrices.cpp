#include "effects/scene/camera_matrices.hpp"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace fx {

CameraMatrices cameraMatrices(const Camera& camera, int width, int height) {
    CameraMatrices m;
    m.aspect = (width > 0 && height > 0) ? float(width) / float(height) : 1.0f;
    m.position = camera.position;
    glm::vec3 direction = viewDirection(camera);
    // Looking straight up or down makes +Y a useless up vector; pick another one.
    glm::vec3 up = std::abs(direction.y) > 0.999f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
    m.view = glm::lookAt(camera.position, camera.position + direction, up);
    m.projection = glm::perspective(glm::radians(verticalFovDegrees(camera, m.aspect)), m.aspect, camera.near,
                                    camera.far);
    m.viewProjection = m.projection * m.view;
    return m;
}

}  // namespace fx
