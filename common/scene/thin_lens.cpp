#include "scene/thin_lens.hpp"

#include <algorithm>
#include <cmath>

namespace fx {
namespace {

// NaN becomes `fallback`; everything else is clamped into [lo, hi].
double clampedOr(double v, double lo, double hi, double fallback) {
    return std::isnan(v) ? fallback : std::clamp(v, lo, hi);
}

}  // namespace

ThinLensModel thinLensModel(const ThinLensInput& in) {
    ThinLensModel m;
    const double lensMm = clampedOr(in.lens.focalLengthMm, kMinFocalMm, kMaxFocalMm, 50.0);
    const double sensorMm = clampedOr(in.lens.sensorWidthMm, 0.01, 1000.0, 36.0);
    const double fNumber = clampedOr(in.lens.fNumber, kMinFNumber, 1.0e4, kMinFNumber);
    // The focus plane stays beyond the focal length: at P = F the sensor would be infinitely far away.
    const double minFocusM = kMinFocusOverFocal * lensMm / 1000.0;
    m.focusM = clampedOr(in.lens.focusDistanceM, minFocusM, 1.0e9, minFocusM);
    const double pMm = m.focusM * 1000.0;
    if (in.convention == CocConvention::chapter) {
        m.imageMm = lensMm;  // (sensor / 2) / tan(fov / 2) with fov = horizontalFovDegrees(lens)
        m.focalMm = 1.0 / (1.0 / pMm + 1.0 / m.imageMm);
        m.radiusPerDiameter = 1.0;
    } else {
        m.focalMm = lensMm;
        m.imageMm = pMm * lensMm / (pMm - lensMm);  // pMm >= 1.001 lensMm: finite, at most 1001 F
        m.radiusPerDiameter = 0.5;
    }
    m.apertureMm = m.focalMm / fNumber;
    m.pixelsPerMm = double(std::max(in.widthPixels, 1)) / sensorMm;
    // c_px = A * I * |1/D - 1/P| * px/mm with D, P in mm; with D, P in m the inverse distances are
    // 1000 times larger, so K (px * m) is A * I * px/mm / 1000.
    m.scalePixelsM = m.apertureMm * m.imageMm * m.pixelsPerMm / 1000.0;
    m.maxCocPixels = clampedOr(in.maxCocPixels, 0.0, 1.0e6, 0.0);
    m.nearM = in.nearM;
    m.farM = in.farM;
    return m;
}

float dofVerticalFovDegrees(const Lens& lens, CocConvention convention, float aspect) {
    if (convention == CocConvention::chapter) return 0.5f * horizontalFovDegrees(lens);
    Camera camera;
    camera.lens = lens;
    return verticalFovDegrees(camera, aspect);
}

double linearDepthM(double depth, double nearM, double farM) {
    double d = clampedOr(depth, 0.0, 1.0, 1.0);
    return nearM * farM / (farM - d * (farM - nearM));
}

double windowDepth(double distanceM, double nearM, double farM) {
    return (farM / (farM - nearM)) * (1.0 - nearM / distanceM);
}

double signedCocPixelsUnclamped(const ThinLensModel& m, double distanceM) {
    return m.scalePixelsM * (1.0 / m.focusM - 1.0 / distanceM);
}

double signedCocPixels(const ThinLensModel& m, double distanceM) {
    return std::clamp(signedCocPixelsUnclamped(m, distanceM), -m.maxCocPixels, m.maxCocPixels);
}

double signedCocPixelsFromDepth(const ThinLensModel& m, double depth) {
    return signedCocPixels(m, linearDepthM(depth, m.nearM, m.farM));
}

}  // namespace fx
