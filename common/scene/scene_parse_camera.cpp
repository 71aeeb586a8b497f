// Reads "camera": position, aim (target or yaw/pitch), projection (fovY or a physical lens), near/far.
#include <cmath>

#include <glm/geometric.hpp>

#include "base/log.hpp"
#include "base/message_text.hpp"
#include "scene/scene_parse.hpp"

namespace fx {
namespace {

constexpr double kFocusMargin = 1.0e-3;

Lens parseLens(JsonFieldReader& reader) {
    Lens lens;
    // Their ranges are declared in scene/scene_settings.cpp (they start lesson 09's parameters); a far
    // mountain is in focus at "infinity".
    lens.focalLengthMm = readSetting(reader, "focalLength", "camera.lens.focalLength", lens.focalLengthMm);
    lens.sensorWidthMm = readSetting(reader, "sensorWidth", "camera.lens.sensorWidth", lens.sensorWidthMm);
    lens.fNumber = readSetting(reader, "fNumber", "camera.lens.fNumber", lens.fNumber);
    lens.focusDistanceM =
        readSetting(reader, "focusDistance", "camera.lens.focusDistance", lens.focusDistanceM);
    // The circle of confusion has (focus distance - focal length) in a denominator: at equality it is
    // infinite, inside the focal length the sign flips. A margin of 0.1% keeps float rounding (0.035 m is
    // not exactly 35 mm in a float) from letting the zero through as a tiny difference.
    double focusMm = double(lens.focusDistanceM) * 1000.0;
    double nearestFocusMm = double(lens.focalLengthMm) * (1.0 + kFocusMargin);
    if (focusMm <= nearestFocusMm) {
        reader.fail(
            "focusDistance",
            cat(formatNumber(lens.focusDistanceM), " m is not beyond the focal length (",
                formatNumber(lens.focalLengthMm),
                " mm): the thin-lens formula divides by (focus distance - focal length), which is zero, negative or lost to rounding here; focus farther than ",
                formatNumber(nearestFocusMm / 1000.0), " m"));
    }
    reader.reportUnknown();
    return lens;
}

void parseAim(JsonFieldReader& reader, Camera& camera) {
    bool hasTarget = reader.has("target");
    bool hasYaw = reader.has("yaw");
    bool hasPitch = reader.has("pitch");
    if (hasTarget && (hasYaw || hasPitch))
        reader.fail(hasYaw ? "yaw" : "pitch", "give either target or yaw and pitch, not both");
    if (hasTarget) {
        camera.aim = CameraAim::target;
        camera.target = reader.vec3("target", camera.target, kCoordinateRange);
        glm::vec3 view = camera.target - camera.position;
        float length = glm::length(view);
        if (!(length > 1.0e-4f))
            reader.fail("target", "equals the camera position, so the view has no direction");
        // A look-at matrix with +Y up has no defined sideways axis when the view is vertical.
        if (std::sqrt(view.x * view.x + view.z * view.z) < 1.0e-3f * length)
            reader.fail(
                "target",
                "is straight above or below the camera; with +Y up the view has no defined sideways direction (move the target a little sideways)");
        return;
    }
    if (!hasYaw && !hasPitch) reader.fail("target", "missing required field (give target, or yaw and pitch)");
    camera.aim = CameraAim::yawPitch;
    camera.yawDegrees = reader.requiredNumber("yaw", NumberRange::closed(-360.0, 360.0));
    // At +-90 degrees the view is vertical: the same look-at problem as above.
    camera.pitchDegrees = reader.requiredNumber("pitch", NumberRange::open(-90.0, 90.0));
}

}  // namespace

Camera parseCamera(JsonFieldReader& reader) {
    Camera camera;
    camera.position = reader.requiredVec3("position", kCoordinateRange);
    parseAim(reader, camera);
    if (reader.has("lens")) {
        if (reader.has("fovY"))
            reader.fail("fovY", "give either fovY or lens, not both (a lens sets the field of view)");
        auto lensReader = reader.object("lens");
        camera.lens = parseLens(lensReader);
    } else {
        camera.fovYDegrees = reader.number("fovY", camera.fovYDegrees, NumberRange::open(0.0, 180.0));
    }
    camera.near = reader.number("near", camera.near, NumberRange::aboveZero(1.0e4));
    camera.far = reader.number("far", camera.far, NumberRange::aboveZero(1.0e7));
    if (camera.far <= camera.near)
        reader.fail("far", cat(formatNumber(camera.far), " is not greater than near (",
                               formatNumber(camera.near), ")"));
    if (camera.far / camera.near > 1.0e5f)
        reader.warn("far", cat("far / near = ", camera.far / camera.near,
                               ": a 24-bit depth buffer will show z-fighting; raise near"));
    reader.reportUnknown();
    return camera;
}

}  // namespace fx
