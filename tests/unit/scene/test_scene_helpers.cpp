// The small computations scenes carry: view direction, lens field of view, motion, model matrix.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/scene.hpp"

namespace {

constexpr float kTolerance = 1.0e-5f;

void expectNear(glm::vec3 a, glm::vec3 b, float tolerance = kTolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(SceneCamera, ViewDirectionFromTargetAndFromYawPitch) {
    fx::Camera camera;
    camera.position = {0, 0, 5};
    camera.target = {0, 0, 0};
    expectNear(fx::viewDirection(camera), {0, 0, -1});
    camera.aim = fx::CameraAim::yawPitch;
    camera.yawDegrees = 0;
    camera.pitchDegrees = 0;
    expectNear(fx::viewDirection(camera), {0, 0, -1});
    camera.yawDegrees = 90;
    expectNear(fx::viewDirection(camera), {1, 0, 0});
    camera.yawDegrees = 0;
    camera.pitchDegrees = 30;
    expectNear(fx::viewDirection(camera), {0, 0.5f, -std::sqrt(3.0f) / 2});
    // A target on the camera (only a scene built in code can have one) still gives a unit vector.
    camera.aim = fx::CameraAim::target;
    camera.target = camera.position;
    EXPECT_NEAR(glm::length(fx::viewDirection(camera)), 1.0f, kTolerance);
}

TEST(SceneCamera, LensFieldOfView) {
    fx::Lens lens;  // 50 mm on 36 mm: 39.6 degrees across
    EXPECT_NEAR(fx::horizontalFovDegrees(lens), 39.5978f, 1.0e-3f);
    fx::Camera camera;
    camera.lens = lens;
    // At 16:9 the sensor is 20.25 mm tall: 2 atan(10.125 / 50) = 22.9 degrees.
    EXPECT_NEAR(fx::verticalFovDegrees(camera, 16.0f / 9.0f), 22.8952f, 1.0e-3f);
    // A 0x0 window gives aspect 0/0 or x/0; the result stays finite.
    EXPECT_TRUE(std::isfinite(fx::verticalFovDegrees(camera, NAN)));
    EXPECT_TRUE(std::isfinite(fx::verticalFovDegrees(camera, INFINITY)));
    EXPECT_TRUE(std::isfinite(fx::verticalFovDegrees(camera, 0.0f)));
    camera.lens.reset();
    camera.fovYDegrees = 55.0f;
    EXPECT_EQ(fx::verticalFovDegrees(camera, 2.0f), 55.0f);
}

TEST(SceneMotion, CircleAndBob) {
    fx::Motion circle{fx::MotionType::circle, 2.0f, 0.0f, 4.0f, 0.0f};
    expectNear(fx::motionOffset(circle, 0.0), {2, 0, 0});
    expectNear(fx::motionOffset(circle, 1.0), {0, 0, 2});
    fx::Motion bob{fx::MotionType::bob, 0.0f, 0.5f, 2.0f, 0.0f};
    expectNear(fx::motionOffset(bob, 0.0), {0, 0, 0});
    expectNear(fx::motionOffset(bob, 1.0), {0, 0.5f, 0});
    expectNear(fx::motionOffset(fx::Motion{}, 3.0), {0, 0, 0});
}

TEST(SceneMotion, StaysExactAfterHoursAndFiniteOnBadTime) {
    fx::Motion circle{fx::MotionType::circle, 2.0f, 0.0f, 4.0f, 90.0f};
    // Ten hours in, a whole number of periods: the same place as at the start.
    expectNear(fx::motionOffset(circle, 36000.0), fx::motionOffset(circle, 0.0), 1.0e-4f);
    expectNear(fx::motionOffset(circle, 36000.0 + 1.0), fx::motionOffset(circle, 1.0), 1.0e-4f);
    glm::vec3 bad = fx::motionOffset(circle, NAN);
    EXPECT_TRUE(std::isfinite(bad.x) && std::isfinite(bad.z));
}

TEST(SceneTransform, ModelMatrixAppliesScaleThenRotationThenTranslation) {
    fx::Transform transform{{1, 2, 3}, {0, 90, 0}, {2, 2, 2}};
    glm::vec4 p = fx::modelMatrix(transform) * glm::vec4(1, 0, 0, 1);
    // (1,0,0) scaled to (2,0,0), turned 90 degrees about Y to (0,0,-2), moved by (1,2,3).
    expectNear(glm::vec3(p), {1, 2, 1});
    fx::Transform xThenY{{0, 0, 0}, {90, 90, 0}, {1, 1, 1}};
    // X first: (0,1,0) -> (0,0,1); then Y: (0,0,1) -> (1,0,0).
    expectNear(glm::vec3(fx::modelMatrix(xThenY) * glm::vec4(0, 1, 0, 0)), {1, 0, 0});
}

}  // namespace
