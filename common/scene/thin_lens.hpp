#pragma once
// The circle of confusion of a thin lens (the Depth of field chapter, §3.2 and §3.4), GL-free so that
// the unit tests check it against the chapter's worked table and the GL tests check the shader
// (shaders/effects/dof/coc.glsl) against it.
//
// Both conventions reduce to one formula. With A the aperture diameter, I the lens-to-sensor distance
// and D, P the object and focus distances, the thin lens gives a blur spot of diameter
//     c_mm = A * F * |P - D| / (D * (P - F)) = A * I * |1/D - 1/P|
// on the sensor (the second form is the first with 1/F = 1/P + 1/I substituted; it has no 0 * inf at
// D = P and no division by P - F). In pixels: c_px = c_mm * width / sensorWidth. So a lens is one
// scale K = A * I * width / sensorWidth, and the signed CoC is K * (1/P - 1/D): negative in front of
// the focus plane (near field), positive behind it (far field).
//
//   corrected  the lens holds its focal length F (the scene's camera.lens) and the sensor moves:
//              I = P F / (P - F); the projection's field of view follows from F and the sensor
//              (verticalFovDegrees); the blur's radius is half the diameter.
//   chapter    the chapter's: the field of view fixes I = (sensor / 2) / tan(fov / 2) (here the lens's
//              focal length, so fov = horizontalFovDegrees(lens)) and F = 1 / (1/P + 1/I) changes with
//              the focus; the projection's vertical field of view is fov * 0.5 (the chapter's mix of
//              a horizontal and a vertical angle); the diameter is used as the radius.
//
// Limits (docs in lessons/09_depth_of_field/lesson.md, "Hard cases"): the focus distance is at least
// kMinFocusOverFocal focal lengths (P <= F, P <= 0 and NaN come to that: the sensor then sits 1000
// focal lengths behind the lens, and everything off the focus plane is blurred up to the clamp); the
// f-number is at least kMinFNumber; the focal length lies in [kMinFocalMm, kMaxFocalMm]; depths are
// clamped to [0, 1] before linearising; the |CoC| is clamped to maxCocPixels.
#include "scene/scene_camera.hpp"

namespace fx {

enum class CocConvention { corrected, chapter };

inline constexpr double kMinFocusOverFocal = 1.001;  // the loader's "0.1% beyond the focal length"
inline constexpr double kMinFNumber = 0.5;           // the limit of a lens in air (numerical aperture 1)
inline constexpr double kMinFocalMm = 0.01;          // a field of view of 179.94 deg on a 36 mm sensor
inline constexpr double kMaxFocalMm = 1.0e6;         // 0.002 deg

struct ThinLensInput {
    Lens lens;
    float nearM = 0.1f;  // the projection's near and far planes (depth is linearised with them)
    float farM = 500.0f;
    int widthPixels = 1280;  // the target's width: pixels per millimetre of sensor
    float maxCocPixels = 16.0f;
    CocConvention convention = CocConvention::corrected;
};

// Everything a shader needs, in one place, with the limits above applied.
struct ThinLensModel {
    double focusM = 10;              // P, after the limits
    double focalMm = 50;             // F (chapter: computed from P and I)
    double imageMm = 50;             // I (corrected: computed from P and F)
    double apertureMm = 17.9;        // A = F / N
    double pixelsPerMm = 35.6;       // width / sensor width
    double scalePixelsM = 0;         // K in px * m: signed CoC diameter = K * (1/P - 1/D), D and P in m
    double radiusPerDiameter = 0.5;  // the blur radius for a CoC: 0.5 corrected, 1 chapter
    double maxCocPixels = 16;
    double nearM = 0.1, farM = 500;
};

ThinLensModel thinLensModel(const ThinLensInput& input);

// The vertical field of view the projection uses with `convention` for a target of `aspect`.
float dofVerticalFovDegrees(const Lens& lens, CocConvention convention, float aspect);

// View-space distance (m, positive) for a window-space depth in [0, 1] of a standard OpenGL projection
// (depth range 0..1): n f / (f - d (f - n)). The chapter's ToRealZ, rewritten without 2d - 1 so that
// depths near 1 lose no precision. Depths outside [0, 1] (and NaN) are clamped first.
double linearDepthM(double depth, double nearM, double farM);
// The inverse: the depth a point at `distanceM` in front of the camera writes.
double windowDepth(double distanceM, double nearM, double farM);

// The signed CoC diameter in pixels at distance D (m), clamped to +-maxCocPixels; 0 at D = P exactly.
double signedCocPixels(const ThinLensModel& model, double distanceM);
// The same, unclamped (for the chapter's table and the tests).
double signedCocPixelsUnclamped(const ThinLensModel& model, double distanceM);
// The same for a window-space depth (what the shader computes from the depth texture).
double signedCocPixelsFromDepth(const ThinLensModel& model, double depth);

}  // namespace fx
