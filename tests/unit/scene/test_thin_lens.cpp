// The circle of confusion (scene/thin_lens.hpp) against the Depth of field chapter's worked table and
// the thin-lens formula written the chapter's way, and its limits (the chapter's hard cases 1 to 4, 9).
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "scene/thin_lens.hpp"

namespace {

using fx::CocConvention;

// The chapter's defaults: N = 1.4, 60 deg across a 36 mm sensor (I = 18 / tan 30 deg), 1280 wide,
// focused on the player at 15.264 m, near 1 m, far 500 m.
fx::ThinLensInput chapterDefaults(CocConvention convention) {
    fx::ThinLensInput in;
    in.lens.sensorWidthMm = 36.0f;
    in.lens.focalLengthMm = float(18.0 / std::tan(M_PI / 6.0));  // horizontalFovDegrees = 60
    in.lens.fNumber = 1.4f;
    in.lens.focusDistanceM = 15.264f;
    in.nearM = 1.0f;
    in.farM = 500.0f;
    in.widthPixels = 1280;
    in.maxCocPixels = 1.0e6f;
    in.convention = convention;
    return in;
}

// The chapter's CalcCoC in double, as it writes it: F from the thin lens with a fixed image distance,
// then |A F (P - D) / (D (P - F))| in mm, times width / sensor width.
double chapterCocPixels(double pM, double dM) {
    const double iMm = 18.0 / std::tan(M_PI / 6.0), pMm = pM * 1000.0, dMm = dM * 1000.0;
    const double fMm = 1.0 / (1.0 / pMm + 1.0 / iMm), aMm = fMm / 1.4;
    return std::abs(aMm * fMm * (pMm - dMm) / (dMm * (pMm - fMm))) * 1280.0 / 36.0;
}

TEST(ThinLens, ChapterLensMatchesTheWorkedValues) {
    fx::ThinLensModel m = fx::thinLensModel(chapterDefaults(CocConvention::chapter));
    // The [derived] figures under the chapter's camera: I = 31.1769, F = 31.113, A = 22.224 mm.
    EXPECT_NEAR(m.imageMm, 31.1769, 5e-5);
    EXPECT_NEAR(m.focalMm, 31.113, 5e-4);
    EXPECT_NEAR(m.apertureMm, 22.224, 5e-4);
    EXPECT_EQ(m.radiusPerDiameter, 1.0);  // the chapter scales the unit disk by the diameter
}

TEST(ThinLens, ChapterTableWithinAThousandthOfAPixel) {
    fx::ThinLensModel m = fx::thinLensModel(chapterDefaults(CocConvention::chapter));
    // Distance (m), CoC (mm) and CoC (px) as the table prints them, with how far its last digit may
    // be off. Two rows are off by one in the last digit: 20 m is 0.01075 mm (printed 0.0108) and 500 m
    // is 1.5647 px (printed 1.57); the formula, not the rounding, is what the 1e-3 px check holds.
    struct Row {
        double dM, mm, mmTolerance, px, pxTolerance;
    };
    const Row table[] = {
        {1, 0.6475, 5e-5, 23.0, 0.05},   {2, 0.3010, 5e-5, 10.7, 0.05},    {5, 0.0932, 5e-5, 3.31, 0.005},
        {10, 0.0239, 5e-5, 0.85, 0.005}, {15.264, 0, 5e-5, 0, 0.0005},     {20, 0.0108, 1e-4, 0.38, 0.005},
        {50, 0.0315, 5e-5, 1.12, 0.005}, {100, 0.0385, 5e-5, 1.37, 0.005}, {500, 0.0440, 5e-5, 1.57, 0.01}};
    for (const Row& r : table) {
        double px = std::abs(fx::signedCocPixelsUnclamped(m, r.dM));
        EXPECT_NEAR(px, chapterCocPixels(15.264, r.dM), 1e-3) << r.dM << " m";
        EXPECT_NEAR(px, r.px, r.pxTolerance) << r.dM << " m";
        EXPECT_NEAR(px / m.pixelsPerMm, r.mm, r.mmTolerance) << r.dM << " m";
    }
    // The infinite limit A F / (P - F) = 0.0454 mm, 1.61 px.
    EXPECT_NEAR(std::abs(fx::signedCocPixelsUnclamped(m, 1e12)), 1.61, 0.005);
    // Other focus distances the chapter works out: P = 5 m blurs 1 m by 19.6 px and 500 m by 4.9 px.
    fx::ThinLensInput at5 = chapterDefaults(CocConvention::chapter);
    at5.lens.focusDistanceM = 5.0f;
    fx::ThinLensModel m5 = fx::thinLensModel(at5);
    EXPECT_NEAR(std::abs(fx::signedCocPixelsUnclamped(m5, 1.0)), 19.6, 0.05);
    EXPECT_NEAR(fx::signedCocPixelsUnclamped(m5, 500.0), 4.9, 0.05);
}

TEST(ThinLens, TheChaptersOtherFocusDistances) {
    // P = 1 m: the background (the sky at far = 500 m) about 23.9 px; P = 100 m: a 1 m object 24.4 px.
    fx::ThinLensInput at1 = chapterDefaults(CocConvention::chapter);
    at1.lens.focusDistanceM = 1.0f;
    EXPECT_NEAR(fx::signedCocPixelsUnclamped(fx::thinLensModel(at1), 500.0), 23.9, 0.05);
    EXPECT_NEAR(chapterCocPixels(1.0, 500.0), 23.9, 0.05);
    fx::ThinLensInput at100 = chapterDefaults(CocConvention::chapter);
    at100.lens.focusDistanceM = 100.0f;
    EXPECT_NEAR(-fx::signedCocPixelsUnclamped(fx::thinLensModel(at100), 1.0), 24.4, 0.05);
    EXPECT_NEAR(chapterCocPixels(100.0, 1.0), 24.4, 0.05);
}

TEST(ThinLens, TheLensThatMatchesTheDisplayedFramingBlursMoreThanTheChapters) {
    // The chapter shows fovY = 60 x 0.5 = 30 deg at 16:9, about 50.9 deg across: a 36 mm sensor behind
    // I = 18 / (tan 15 deg x 16/9) = 37.79 mm. At f/1.4 focused on 15.264 m that lens has F = 37.69 mm
    // and A = 26.92 mm, and blurs a 1 m object by 33.8 px: the chapter's 23.0 px is 0.68 of it.
    fx::ThinLensInput shown = chapterDefaults(CocConvention::chapter);
    shown.lens.focalLengthMm = float(18.0 / (std::tan(M_PI / 12.0) * 16.0 / 9.0));
    EXPECT_NEAR(fx::horizontalFovDegrees(shown.lens), 50.9, 0.05);
    fx::ThinLensModel m = fx::thinLensModel(shown);
    EXPECT_NEAR(m.imageMm, 37.79, 0.005);
    EXPECT_NEAR(m.focalMm, 37.69, 0.005);
    EXPECT_NEAR(m.apertureMm, 26.92, 0.005);
    const double matched = std::abs(fx::signedCocPixelsUnclamped(m, 1.0));
    EXPECT_NEAR(matched, 33.8, 0.05);
    const double chapter = std::abs(
        fx::signedCocPixelsUnclamped(fx::thinLensModel(chapterDefaults(CocConvention::chapter)), 1.0));
    EXPECT_NEAR(chapter / matched, 0.68, 0.005);
}

TEST(ThinLens, SignSaysNearOrFarField) {
    fx::ThinLensModel m = fx::thinLensModel(chapterDefaults(CocConvention::corrected));
    EXPECT_LT(fx::signedCocPixels(m, 2.0), 0.0);
    EXPECT_GT(fx::signedCocPixels(m, 50.0), 0.0);
    EXPECT_EQ(fx::signedCocPixels(m, m.focusM), 0.0);  // no 0 * infinity at the focus plane
}

TEST(ThinLens, CorrectedConventionHalvesTheChaptersRadiusAndKeepsTheFocalLength) {
    fx::ThinLensModel chapter = fx::thinLensModel(chapterDefaults(CocConvention::chapter));
    fx::ThinLensModel corrected = fx::thinLensModel(chapterDefaults(CocConvention::corrected));
    EXPECT_NEAR(corrected.focalMm, 31.1769, 5e-5);
    // I = P F / (P - F) = 31.2408 mm; A = F / N = 22.2692 mm.
    EXPECT_NEAR(corrected.imageMm, 15264.0 * 31.1769 / (15264.0 - 31.1769), 1e-3);
    EXPECT_NEAR(corrected.apertureMm, 31.1769 / 1.4, 1e-4);
    EXPECT_EQ(corrected.radiusPerDiameter, 0.5);
    // Diameters at 1 m: A I |1/D - 1/P| px/mm.
    double diameter = std::abs(fx::signedCocPixelsUnclamped(corrected, 1.0));
    EXPECT_NEAR(diameter, 22.2692 * 31.2408 * (1.0 / 1000.0 - 1.0 / 15264.0) * 1280.0 / 36.0, 2e-3);
    // The blur's radius: the chapter's is the diameter, the corrected one half of it.
    double chapterRadius = std::abs(fx::signedCocPixelsUnclamped(chapter, 1.0)) * chapter.radiusPerDiameter;
    EXPECT_NEAR(diameter * corrected.radiusPerDiameter / chapterRadius, 0.5 * 1.00410, 1e-4);
}

TEST(ThinLens, ProjectionFieldOfViewPerConvention) {
    fx::Lens lens = chapterDefaults(CocConvention::chapter).lens;
    // The chapter passes fov * 0.5 as the vertical angle; the lens's own framing at 16:9 is 35.98 deg.
    EXPECT_NEAR(fx::dofVerticalFovDegrees(lens, CocConvention::chapter, 16.0f / 9.0f), 30.0, 1e-4);
    EXPECT_NEAR(fx::dofVerticalFovDegrees(lens, CocConvention::corrected, 16.0f / 9.0f), 35.983, 1e-3);
}

TEST(ThinLens, DepthLinearisesBothWays) {
    for (double d : {1.0, 2.0, 15.264, 100.0, 499.0}) {
        double depth = fx::windowDepth(d, 1.0, 500.0);
        EXPECT_NEAR(fx::linearDepthM(depth, 1.0, 500.0), d, 1e-9 * d * d);
    }
    EXPECT_DOUBLE_EQ(fx::linearDepthM(0.0, 1.0, 500.0), 1.0);
    EXPECT_DOUBLE_EQ(fx::linearDepthM(1.0, 1.0, 500.0), 500.0);  // sky: the far plane, finite
    EXPECT_DOUBLE_EQ(fx::linearDepthM(1.5, 1.0, 500.0), 500.0);  // beyond far: clamped
    EXPECT_DOUBLE_EQ(fx::linearDepthM(-1.0, 1.0, 500.0), 1.0);
    EXPECT_DOUBLE_EQ(fx::linearDepthM(std::nan(""), 1.0, 500.0), 500.0);
    // The naive step's 0.935: the raw depth of 15.26 m under the chapter's old projection (1, 1000).
    EXPECT_NEAR(fx::windowDepth(15.264, 1.0, 1000.0), 0.935, 5e-4);
}

// Hard cases 1 to 4: whatever the sliders say, the model stays finite and the CoC is clamped.
TEST(ThinLens, FocusAtOrInsideTheFocalLengthHasADefinedLimit) {
    for (CocConvention c : {CocConvention::corrected, CocConvention::chapter}) {
        for (float focus :
             {0.0311769f, 0.03f, 0.001f, 0.0f, -1.0f, -0.0311769f, std::numeric_limits<float>::quiet_NaN(),
              std::numeric_limits<float>::infinity()}) {
            fx::ThinLensInput in = chapterDefaults(c);
            in.lens.focusDistanceM = focus;
            in.maxCocPixels = 32.0f;
            fx::ThinLensModel m = fx::thinLensModel(in);
            EXPECT_TRUE(std::isfinite(m.scalePixelsM)) << focus;
            EXPECT_GE(m.focusM, 1.001 * 0.0311769 - 1e-9) << focus;
            for (double d : {0.01, 0.5, 1.0, 15.0, 500.0, 1e9}) {
                double coc = fx::signedCocPixels(m, d);
                EXPECT_TRUE(std::isfinite(coc)) << focus << " " << d;
                EXPECT_LE(std::abs(coc), 32.0) << focus << " " << d;
            }
        }
    }
    // The limit: focused at the focal length means focused at 1.001 focal lengths, the sensor 1001
    // focal lengths behind the lens.
    fx::ThinLensInput in = chapterDefaults(CocConvention::corrected);
    in.lens.focusDistanceM = in.lens.focalLengthMm / 1000.0f;
    fx::ThinLensModel m = fx::thinLensModel(in);
    EXPECT_NEAR(m.imageMm / m.focalMm, 1001.0, 1e-6);
}

TEST(ThinLens, FNumberNearZeroAndFieldOfViewExtremesStayFinite) {
    for (float n : {0.0f, 1e-6f, -2.0f}) {
        fx::ThinLensInput in = chapterDefaults(CocConvention::corrected);
        in.lens.fNumber = n;
        in.maxCocPixels = 32.0f;
        fx::ThinLensModel m = fx::thinLensModel(in);
        EXPECT_NEAR(m.apertureMm, m.focalMm / 0.5, 1e-9);  // f/0.5 at most
        EXPECT_EQ(std::abs(fx::signedCocPixels(m, 1.0)), 32.0);
    }
    for (double fov : {1e-4, 0.01, 179.0, 179.99}) {
        for (CocConvention c : {CocConvention::corrected, CocConvention::chapter}) {
            fx::ThinLensInput in = chapterDefaults(c);
            in.lens.focalLengthMm = float(18.0 / std::tan(fov * M_PI / 360.0));
            in.maxCocPixels = 32.0f;
            fx::ThinLensModel m = fx::thinLensModel(in);
            for (double d : {0.5, 15.264, 500.0}) {
                double coc = fx::signedCocPixels(m, d);
                EXPECT_TRUE(std::isfinite(coc) && std::abs(coc) <= 32.0) << fov << " " << d;
            }
            float vfov = fx::dofVerticalFovDegrees(in.lens, c, 16.0f / 9.0f);
            EXPECT_TRUE(std::isfinite(vfov) && vfov > 0.0f && vfov < 180.0f) << fov;
        }
    }
    // Near 180 deg the blur vanishes (I -> 0); near 0 deg it grows without bound and is clamped.
    fx::ThinLensInput wide = chapterDefaults(CocConvention::corrected);
    wide.lens.focalLengthMm = float(18.0 / std::tan(179.9 * M_PI / 360.0));
    EXPECT_LT(std::abs(fx::signedCocPixels(fx::thinLensModel(wide), 1.0)), 1e-3);
    fx::ThinLensInput tele = chapterDefaults(CocConvention::corrected);
    tele.lens.focalLengthMm = float(18.0 / std::tan(0.01 * M_PI / 360.0));
    tele.maxCocPixels = 32.0f;
    EXPECT_EQ(fx::signedCocPixels(fx::thinLensModel(tele), 500.0), 32.0);
}

TEST(ThinLens, ClampedToMaxCoc) {
    fx::ThinLensInput in = chapterDefaults(CocConvention::chapter);
    in.maxCocPixels = 8.0f;
    fx::ThinLensModel m = fx::thinLensModel(in);
    EXPECT_EQ(fx::signedCocPixels(m, 1.0), -8.0);
    EXPECT_EQ(fx::signedCocPixels(m, 0.0), -8.0);  // 1/0: infinity, clamped
    EXPECT_NEAR(fx::signedCocPixels(m, 500.0), chapterCocPixels(15.264, 500.0), 1e-3);  // under the clamp
}

}  // namespace
