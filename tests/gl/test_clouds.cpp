// The cloud pass's rays against the slab (the Clouds chapter's hard cases in its part 8): from above,
// from inside, parallel to the faces, stopped by depth, rejected behind the eye; sample counts and
// Beer-Lambert; which settings share a program. Read back as floats (test_clouds_harness.hpp).
#include "test_clouds_harness.hpp"

using namespace fx;
using namespace fx::test;

namespace {

TEST_F(CloudsOnGl, LookingDownFromAboveEveryRayTakesAllEightSamples) {
    Camera cam = cameraAt({0, 5, 0}, 0, -89.5f);
    FloatImage out = run(marchSettings(cam, 3, 3), 3, 3, constant);
    ASSERT_TRUE(allFinite(out));
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x)
            EXPECT_NEAR(alphaAt(out, x, y), chapterOpacity(a, 8), kTolerance) << x << "," << y;
    // rgb = colour x opacity over a black target: the colour is white.
    EXPECT_NEAR(out.texel(1, 1, 0), alphaAt(out, 1, 1), kTolerance);
}

TEST_F(CloudsOnGl, EyeInsideTheSlabMarchesFromTheEyeOnlyWithTheChaptersFix) {
    // Eye at 1.1 m looking down: samples at 1.1, 0.85, 0.6, 0.35, 0.1 m are in the slab, the rest below it.
    Camera cam = cameraAt({0, 1.1f, 0}, 0, -89.5f);
    CloudFrameSettings fixed = marchSettings(cam, 3, 3);
    FloatImage out = run(fixed, 3, 3, constant);
    ASSERT_TRUE(allFinite(out));
    EXPECT_NEAR(alphaAt(out, 1, 1), chapterOpacity(a, 5), kTolerance);
    // Step 5 (before the fix): the bottom face is ahead but the top face behind, tmin < 0: nothing.
    CloudFrameSettings before = fixed;
    before.features &= ~cloudEyeInside;
    FloatImage none = run(before, 3, 3, constant);
    EXPECT_EQ(alphaAt(none, 1, 1), 0.0f);
}

TEST_F(CloudsOnGl, ARayParallelToTheSlabIsFiniteInsideOnTheFacesAndOutside) {
    // An odd height puts the middle row's pixel centres exactly on the horizon: v.y == 0.
    const int w = 5, h = 5;
    struct Case {
        float eyeY;
        float expected;
    };
    for (Case c : {Case{1.0f, chapterOpacity(a, 8)}, Case{0.0f, chapterOpacity(a, 8)},
                   Case{2.0f, chapterOpacity(a, 8)}, Case{3.0f, 0.0f}, Case{-1.0f, 0.0f}}) {
        Camera cam = cameraAt({0, c.eyeY, 0}, 0, 0);
        FloatImage out = run(marchSettings(cam, w, h), w, h, constant);
        ASSERT_TRUE(allFinite(out)) << "eye at " << c.eyeY;
        for (int x = 0; x < w; ++x)
            EXPECT_NEAR(alphaAt(out, x, h / 2), c.expected, kTolerance) << "eye at " << c.eyeY << ", x " << x;
    }
}

TEST_F(CloudsOnGl, EyeOnTheTopFaceLookingDownStartsAtTheEye) {
    Camera cam = cameraAt({0, 2.0f, 0}, 0, -89.5f);
    FloatImage out = run(marchSettings(cam, 3, 3), 3, 3, constant);
    ASSERT_TRUE(allFinite(out));
    EXPECT_NEAR(alphaAt(out, 1, 1), chapterOpacity(a, 8), kTolerance);
}

TEST_F(CloudsOnGl, DepthFromASurfaceStopsTheRayThereAndSkyDoesNot) {
    Camera cam = cameraAt({0, 5, 0}, 0, -89.5f);
    CloudFrameSettings s = marchSettings(cam, 3, 3);
    // A surface 1 m under the eye (above the slab) hides it all; one at 1.1 m height (3.9 m under the
    // eye) leaves the samples at 2, 1.75, 1.5 and 1.25 m.
    std::vector<float> above(9, depthForViewZ(s.projection, -1.0f));
    std::vector<float> inside(9, depthForViewZ(s.projection, -3.9f));
    FloatImage hidden = run(s, 3, 3, constant, above);
    FloatImage partly = run(s, 3, 3, constant, inside);
    ASSERT_TRUE(allFinite(hidden));
    ASSERT_TRUE(allFinite(partly));
    EXPECT_EQ(alphaAt(hidden, 1, 1), 0.0f);
    EXPECT_NEAR(alphaAt(partly, 1, 1), chapterOpacity(a, 4), kTolerance);
    // Sky (depth exactly 1): the whole slab.
    FloatImage sky = run(s, 3, 3, constant, std::vector<float>(9, 1.0f));
    EXPECT_NEAR(alphaAt(sky, 1, 1), chapterOpacity(a, 8), kTolerance);
}

TEST_F(CloudsOnGl, ALevelRayInsideTheSlabStopsAtANearbyWallOnlyByDistance) {
    // Hard case 4: the eye inside the slab looking level at a wall 3 m away. The chapter's height test
    // cannot tell in front from behind when y does not change along the ray: all 8 samples count,
    // 20 m of them through the wall. Compared by distance, only the samples at 0 and 2.5 m do.
    const int w = 5, h = 5;
    Camera cam = cameraAt({0, 1, 0}, 0, 0);
    CloudFrameSettings s = marchSettings(cam, w, h);
    std::vector<float> wall(std::size_t(w * h), depthForViewZ(s.projection, -3.0f));
    FloatImage byHeight = run(s, w, h, constant, wall);
    s.features |= cloudDistanceOcclusion;
    FloatImage byDistance = run(s, w, h, constant, wall);
    ASSERT_TRUE(allFinite(byHeight));
    ASSERT_TRUE(allFinite(byDistance));
    EXPECT_NEAR(alphaAt(byHeight, w / 2, h / 2), chapterOpacity(a, 8), kTolerance);
    EXPECT_NEAR(alphaAt(byDistance, w / 2, h / 2), chapterOpacity(a, 2), kTolerance);
}

TEST_F(CloudsOnGl, ThresholdOneEqualFacesAndNoSamplesGiveNoCloudAndNoNaN) {
    Camera cam = cameraAt({0, 5, 0}, 0, -89.5f);
    CloudFrameSettings base = marchSettings(cam, 3, 3);
    base.features |= cloudThreshold | cloudHeightShaping | cloudShadows;

    CloudFrameSettings threshold1 = base;
    threshold1.march = cloudMarch(0.0f, 2.0f, 8.0f, 1.0f);
    CloudFrameSettings flat = base;
    flat.march = cloudMarch(1.0f, 1.0f, 8.0f, 0.5f);
    CloudFrameSettings noSamples = base;
    noSamples.march = cloudMarch(0.0f, 2.0f, 0.0f, 0.5f);
    for (const CloudFrameSettings* s : {&threshold1, &flat, &noSamples}) {
        FloatImage out = run(*s, 3, 3, constant);
        ASSERT_TRUE(allFinite(out));
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 3; ++x) EXPECT_EQ(alphaAt(out, x, y), 0.0f);
    }
    // Just below 1: a huge gain, every sample clamped to full opacity, still finite.
    CloudFrameSettings almost = base;
    almost.march = cloudMarch(0.0f, 2.0f, 8.0f, 0.9999f);
    FloatImage out = run(almost, 3, 3, constant);
    ASSERT_TRUE(allFinite(out));
    EXPECT_LE(alphaAt(out, 1, 1), 1.0f);
}

TEST_F(CloudsOnGl, OneSampleAndANonIntegerCount) {
    Camera cam = cameraAt({0, 5, 0}, 0, -89.5f);
    CloudFrameSettings one = marchSettings(cam, 3, 3);
    one.march = cloudMarch(0.0f, 2.0f, 1.0f, 0.5f);
    EXPECT_NEAR(alphaAt(run(one, 3, 3, constant), 1, 1), chapterOpacity(a, 1), kTolerance);
    CloudFrameSettings eightAndAHalf = marchSettings(cam, 3, 3);
    eightAndAHalf.march = cloudMarch(0.0f, 2.0f, 8.5f, 0.5f);
    EXPECT_NEAR(alphaAt(run(eightAndAHalf, 3, 3, constant), 1, 1), chapterOpacity(a, 8), kTolerance);
}

TEST_F(CloudsOnGl, BeerLambertConvergesWithTheSampleCount) {
    // Beyond the chapter: opacity from each step's length, so 16 and 512 samples agree, where the
    // chapter's constant 0.3 a sample would go from 0.6 to fully opaque.
    Camera cam = cameraAt({0, 5, 0}, 0, -89.5f);
    CloudFrameSettings s = marchSettings(cam, 3, 3);
    s.features |= cloudBeerLambert;
    s.march = cloudMarch(0.0f, 2.0f, 16.0f, 0.5f);
    float at16 = alphaAt(run(s, 3, 3, constant), 1, 1);
    s.march = cloudMarch(0.0f, 2.0f, 512.0f, 0.5f);
    float at512 = alphaAt(run(s, 3, 3, constant), 1, 1);
    // Exactly 1 - exp(-sigma a L): sigma = 0.3 x 8 / thickness, L the slab's 2 m (straight down).
    float exact = 1.0f - std::exp(-0.3f * 8.0f / 2.0f * a * 2.0f);
    EXPECT_NEAR(at16, exact, 5e-3f);
    EXPECT_NEAR(at512, exact, 5e-3f);
}

TEST_F(CloudsOnGl, HitsBehindTheEyeAreRejectedOtherwiseTheLayerIsMirroredInTheSky) {
    // The plane at 1 m, the eye at 6 m looking up: every hit is behind the eye.
    Camera cam = cameraAt({0, 6, 0}, 0, 35.0f);
    CloudFrameSettings s = marchSettings(cam, 8, 8);
    s.stage = CloudStage::plane;
    s.planeHeight = 1.0f;
    s.features = cloudRejectBehind;
    FloatImage rejected = run(s, 8, 8, constant);
    s.features = 0;
    FloatImage mirrored = run(s, 8, 8, constant);
    ASSERT_TRUE(allFinite(rejected));
    ASSERT_TRUE(allFinite(mirrored));
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x) {
            EXPECT_EQ(alphaAt(rejected, x, y), 0.0f);
            EXPECT_GT(alphaAt(mirrored, x, y), 0.1f);
        }
    }
}

// The stage, the features, the dither and the premultiplied output are #defines (one program each,
// so llvmpipe does not run every alternative); a bit or a dither the stage's code never reads must not
// build another program for the same picture.
TEST_F(CloudsOnGl, SettingsThatDrawTheSamePictureShareOneProgram) {
    CloudFrameSettings screen;
    screen.stage = CloudStage::screenTexture;
    CloudFrameSettings screenWithEverything = screen;
    screenWithEverything.features = cloudShadows | cloudTwoScales | cloudBeerLambert;
    screenWithEverything.dither = CloudDither::r2;
    EXPECT_EQ(&pass.programFor(screen), &pass.programFor(screenWithEverything));

    CloudFrameSettings plane;
    plane.stage = CloudStage::plane;
    plane.features = cloudRejectBehind | cloudTwoScales;
    CloudFrameSettings planeWithMarchBits = plane;
    planeWithMarchBits.features |= cloudShadows | cloudEyeInside | cloudBeerLambert;
    planeWithMarchBits.dither = CloudDither::bayer;
    EXPECT_EQ(&pass.programFor(plane), &pass.programFor(planeWithMarchBits));
    EXPECT_NE(&pass.programFor(plane), &pass.programFor(screen));

    // What the march reads is a program of its own: the dither, a feature bit, premultiplied output.
    CloudFrameSettings march;
    march.stage = CloudStage::march;
    march.features = cloudEyeInside;
    CloudFrameSettings bayer = march;
    bayer.dither = CloudDither::bayer;
    CloudFrameSettings shadows = march;
    shadows.features |= cloudShadows;
    CloudFrameSettings premultiplied = march;
    premultiplied.premultiplied = true;
    CloudFrameSettings rejectBehind = march;  // a plane-only bit: the same march
    rejectBehind.features |= cloudRejectBehind;
    const FullscreenPass* m = &pass.programFor(march);
    EXPECT_NE(m, &pass.programFor(bayer));
    EXPECT_NE(m, &pass.programFor(shadows));
    EXPECT_NE(m, &pass.programFor(premultiplied));
    EXPECT_EQ(m, &pass.programFor(rejectBehind));
    for (const CloudFrameSettings* s : {&screen, &plane, &march, &bayer, &shadows, &premultiplied})
        EXPECT_TRUE(pass.programFor(*s).reloadable().usable()) << pass.programFor(*s).reloadable().error();
}

}  // namespace
