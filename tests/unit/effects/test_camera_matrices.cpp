// The camera's projection against the Shader effects chapter's numbers: degFovY = 60 gives
// fovScale = 1 / tan(30 degrees) = 1.7320508 on the projection's y axis, x is that over the aspect of the
// framebuffer (not the window), and a point 30 degrees above the view axis lands on the top edge.
#include <cmath>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "effects/scene/camera_matrices.hpp"

namespace {

using namespace fx;

TEST(CameraMatrices, SixtyDegreesVerticalIsTheChaptersFovScale1Point7320508) {
    Camera camera;  // fovY 60, the chapter's degFovY
    camera.position = {3, 1, 3};
    camera.aim = CameraAim::yawPitch;
    ASSERT_EQ(camera.fovYDegrees, 60.0f);
    const CameraMatrices m = cameraMatrices(camera, 1920, 1080);
    EXPECT_NEAR(m.projection[1][1], 1.7320508f, 1e-6f);
    EXPECT_NEAR(m.projection[0][0], 1.7320508f / (1920.0f / 1080.0f), 1e-6f);

    // 30 degrees above the axis, 10 m ahead: the top edge of the picture (NDC y = 1), centred in x.
    const glm::vec3 ahead = viewDirection(camera);
    const glm::vec3 point =
        camera.position + 10.0f * ahead + glm::vec3(0, 10.0f * std::tan(glm::radians(30.0f)), 0);
    const glm::vec4 clip = m.viewProjection * glm::vec4(point, 1.0f);
    EXPECT_NEAR(clip.y / clip.w, 1.0f, 1e-5f);
    EXPECT_NEAR(clip.x / clip.w, 0.0f, 1e-5f);

    // A minimised window (0x0) keeps the same fovScale with an aspect of 1, nothing divided by 0.
    const CameraMatrices minimised = cameraMatrices(camera, 0, 0);
    EXPECT_NEAR(minimised.projection[1][1], 1.7320508f, 1e-6f);
    EXPECT_NEAR(minimised.projection[0][0], 1.7320508f, 1e-6f);
}

}  // namespace
