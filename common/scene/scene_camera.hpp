#pragma once
// The camera a scene asks for: where it stands, where it looks, and how it projects. Projection is
// either a plain vertical field of view or a physical lens; depth of field needs the lens.
#include <optional>

#include <glm/vec3.hpp>

namespace fx {

// A thin lens in front of a sensor, in the units photographers use. The thin-lens formula divides by
// (focus distance - focal length), so the loader refuses a focus distance at or inside the focal length.
struct Lens {
    float focalLengthMm = 50.0f;
    float sensorWidthMm = 36.0f;  // 35 mm full frame
    float fNumber = 2.8f;
    float focusDistanceM = 10.0f;

    bool operator==(const Lens&) const = default;
};

enum class CameraAim { target, yawPitch };

struct Camera {
    glm::vec3 position{0.0f, 2.0f, 8.0f};
    CameraAim aim = CameraAim::target;
    glm::vec3 target{0.0f};     // aim == target; never equal to position
    float yawDegrees = 0.0f;    // aim == yawPitch: 0 looks down -Z, 90 looks down +X
    float pitchDegrees = 0.0f;  // aim == yawPitch: positive looks up; |pitch| < 90
    float fovYDegrees = 60.0f;  // used only without a lens
    std::optional<Lens> lens;
    float near = 0.1f;
    float far = 500.0f;

    bool operator==(const Camera&) const = default;
};

// Unit vector the camera looks along (+Y is up).
glm::vec3 viewDirection(const Camera& camera);

// Field of view across the sensor width: 2 atan(sensor width / (2 focal length)).
float horizontalFovDegrees(const Lens& lens);

// The vertical field of view the projection matrix needs. With a lens it follows from the sensor width
// and the aspect ratio (width / height), so the picture and the depth-of-field maths agree on one focal
// length. An aspect that is not a positive finite number (a 0x0 window) counts as 1.
float verticalFovDegrees(const Camera& camera, float aspect);

}  // namespace fx
