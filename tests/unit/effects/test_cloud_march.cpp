// The cloud pass's CPU side (effects/clouds): the wrapped scroll, the guarded slab and threshold
// numbers, the dither tables and the camera folded into the texture offsets. The Clouds chapter's
// pitfalls (offset precision) and hard cases 8, 9, 10 and 12.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "effects/clouds/cloud_march.hpp"
#include "effects/clouds/cloud_pass.hpp"

namespace {

using namespace fx;

const glm::dvec4 kChapterSpeed{-0.0019, -0.0041, -0.0027, -0.0013};
const glm::dvec4 kChapterStart{0.0, 0.0, 0.3, 0.7};
constexpr double kFrame = 1.0 / 60.0;
constexpr double kHour = 3600.0;

// How far a component moved in one step, on the circle of the repeat (the texture wraps).
double moved(float before, float after) {
    double d = double(after) - double(before);
    return d - std::round(d);
}

TEST(CloudScroll, AFrameAt200HoursMovesAsFarAsAFrameInTheFirstMinute) {
    for (double t : {60.0, 200.0 * kHour}) {
        CloudScroll s = CloudScroll::at(kChapterStart, kChapterSpeed, t);
        glm::vec4 before = s.offset();
        s.advance(kChapterSpeed, kFrame);
        glm::vec4 after = s.offset();
        for (int i = 0; i < 4; ++i) {
            double expected = kChapterSpeed[i] * kFrame;
            EXPECT_NEAR(moved(before[i], after[i]), expected, 0.01 * std::abs(expected))
                << "component " << i << " at " << t / kHour << " h";
            EXPECT_GE(after[i], 0.0f);
            EXPECT_LT(after[i], 1.0f);
        }
    }
}

TEST(CloudScroll, TheChaptersUnwrappedFloatStallsAt200Hours) {
    // The pitfall the wrap removes: the fastest component, a float near -2952 after 200 h, cannot
    // take a step of 6.8e-5 (its spacing there is 2.4e-4), so the clouds stop.
    glm::vec4 offset = glm::vec4(kChapterStart + kChapterSpeed * (200.0 * kHour));
    glm::vec4 next = unwrappedCloudOffsetStep(offset, glm::vec4(kChapterSpeed), float(kFrame));
    EXPECT_EQ(next.y, offset.y);
}

TEST(CloudScroll, StaysInTheRepeatOverManyFramesAndIgnoresNonFiniteInput) {
    CloudScroll s;
    for (int i = 0; i < 100000; ++i) s.advance(glm::dvec4(0.37, -0.91, 3.1, -7.3), kFrame);
    for (int i = 0; i < 4; ++i) {
        EXPECT_GE(s.exact()[i], 0.0);
        EXPECT_LT(s.exact()[i], 1.0);
    }
    glm::dvec4 kept = s.exact();
    s.advance(glm::dvec4(NAN, INFINITY, 0.0, 0.0), kFrame);
    s.advance(kChapterSpeed, NAN);
    EXPECT_EQ(s.exact().x, kept.x);
    EXPECT_EQ(s.exact().y, kept.y);
}

TEST(CloudMarch, TheChaptersDefaults) {
    CloudMarch m = cloudMarch(0.0f, 2.0f, 8.0f, 0.5f);
    EXPECT_TRUE(m.drawn);
    EXPECT_EQ(m.steps, 8);
    EXPECT_FLOAT_EQ(m.stepHeight, 0.25f);
    EXPECT_FLOAT_EQ(m.thresholdGain, 2.0f);
    EXPECT_FALSE(m.thresholdClears);
}

TEST(CloudMarch, ThresholdOneOrMoreLeavesNoCloudAndNoInfinity) {
    for (float th : {1.0f, 1.5f, NAN}) {
        CloudMarch m = cloudMarch(0.0f, 2.0f, 8.0f, th);
        EXPECT_TRUE(m.thresholdClears) << th;
        EXPECT_EQ(m.thresholdGain, 0.0f) << th;
    }
    CloudMarch nearOne = cloudMarch(0.0f, 2.0f, 8.0f, 0.9999f);
    EXPECT_TRUE(std::isfinite(nearOne.thresholdGain));
    EXPECT_GT(nearOne.thresholdGain, 1000.0f);  // a large gain, kept: the shader clamps each sample
}

TEST(CloudMarch, EqualOrSwappedFacesAndNoSamplesMarchNothing) {
    for (auto [bottom, top, steps] :
         {std::tuple{1.0f, 1.0f, 8.0f}, std::tuple{3.0f, 1.0f, 8.0f}, std::tuple{0.0f, 2.0f, 0.0f},
          std::tuple{0.0f, 2.0f, 0.5f}, std::tuple{0.0f, 2.0f, -4.0f}, std::tuple{0.0f, 2.0f, NAN}}) {
        CloudMarch m = cloudMarch(bottom, top, steps, 0.5f);
        EXPECT_FALSE(m.drawn) << bottom << " " << top << " " << steps;
        EXPECT_EQ(m.stepHeight, 0.0f);
        glm::vec4 u = m.rangeCountStep();
        for (int i = 0; i < 4; ++i) EXPECT_TRUE(std::isfinite(u[i]));
    }
}

TEST(CloudMarch, ANonIntegerCountCrossesTheWholeSlab) {
    // The chapter divides by 8.5 and runs 8 samples: 8 x 2/8.5 = 1.88 of 2 m. Here both use 8.
    CloudMarch m = cloudMarch(0.0f, 2.0f, 8.5f, 0.5f);
    EXPECT_EQ(m.steps, 8);
    EXPECT_FLOAT_EQ(m.stepHeight * float(m.steps), 2.0f);
    EXPECT_EQ(cloudMarch(0.0f, 2.0f, 100000.0f, 0.5f).steps, kCloudMaxSteps);
}

TEST(CloudDither, BayerIsTheChaptersMatrixWithEveryPhaseOnce) {
    EXPECT_EQ(bayer4x4(0, 0), 0.0f);
    EXPECT_EQ(bayer4x4(1, 0), 8.0f / 16.0f);
    EXPECT_EQ(bayer4x4(0, 1), 12.0f / 16.0f);
    EXPECT_EQ(bayer4x4(3, 3), 5.0f / 16.0f);
    std::set<float> phases;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) phases.insert(bayer4x4(x + 8, y + 12));  // window-relative: repeats
    EXPECT_EQ(phases.size(), 16u);
}

TEST(CloudDither, InterleavedGradientNoiseIsInRangeAndMovesWithTheFrame) {
    int changed = 0;
    for (int i = 0; i < 64; ++i) {
        float a = interleavedGradientNoise(float(i), float(3 * i), 0);
        float b = interleavedGradientNoise(float(i), float(3 * i), 1);
        EXPECT_GE(a, 0.0f);
        EXPECT_LT(a, 1.0f);
        changed += a != b;
    }
    EXPECT_GT(changed, 60);
}

TEST(CloudOffsets, ACamera10KmAwayGetsSmallOffsetsAndTheSamePattern) {
    // 1/256 repeats per metre (exact in float): 10.24 km is exactly 40 repeats, so the texture under
    // the camera is the same as at the origin, and the shader's offsets must be the same.
    CloudFrameSettings near, far;
    near.scales = far.scales = {1.0f / 256.0f, 1.0f / 128.0f};
    near.scrollOffset = far.scrollOffset = glm::vec4(0.1f, 0.2f, 0.3f, 0.7f);
    far.cameraPosition = glm::vec3(10240.0f, 5.0f, -10240.0f);
    glm::vec4 a = cloudShaderOffsets(near), b = cloudShaderOffsets(far);
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(moved(a[i], b[i]), 0.0, 1e-6) << i;
        EXPECT_GE(b[i], 0.0f);
        EXPECT_LT(b[i], 1.0f);
    }
}

TEST(CloudShadow, TheOffsetIsOneTexelOfTheShadowMapItself) {
    ShadowLookup lookup;
    lookup.light.halfWidth = 150.0f;
    lookup.light.texelWorldSize = 300.0f / 1024.0f;  // the chapter's 150 m range on a 1024 map
    lookup.filterTaps = 16;
    lookup.normalOffsetMetres = 0.4f;
    EXPECT_FLOAT_EQ(cloudShadowOffset(lookup), 0.29296875f);
    ShadowLookup c = cloudShadowLookup(lookup);
    EXPECT_EQ(c.normalOffsetMetres, 0.0f);
    EXPECT_LE(c.filterTaps, 4);
}

}  // namespace
