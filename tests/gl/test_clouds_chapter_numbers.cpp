// The Clouds chapter's numbers in lesson 08's picture, read back as floats: the height factor (1 at the
// slab's bottom, 0.5 at its top, before the threshold), the threshold's remap clamp(a - t, 0, 1) / (1 - t),
// the object shadow's darkening 0.5 x min(S, 1), lookups outside the shadow map counted as lit (hard case
// 13), each layer's world drift (-speed / scale: (+0.59, +1.28) and (+0.34, +0.17) m/s) and the two
// scales' period lcm(311, 127) = 39,497 m.
#include <numeric>

#include "test_clouds_harness.hpp"

using namespace fx;
using namespace fx::test;

namespace {

// Straight down from above the slab, or straight up from below it: the first sample lies exactly on
// the face the ray enters (the top or the bottom), the next ones a vertical step further.
Camera lookingDown() {
    return cameraAt({0, 5, 0}, 0, -89.9f);
}
Camera lookingUp() {
    return cameraAt({0, -3, 0}, 0, 89.9f);
}

TEST_F(CloudsOnGl, HeightShapingIsOneAtTheBottomAndOneHalfAtTheTopBeforeTheThreshold) {
    const int w = 9, h = 9;
    auto opacity = [&](const Camera& cam, int steps, bool shaping) {
        CloudFrameSettings s = marchSettings(cam, w, h);
        s.march = cloudMarch(0.0f, 2.0f, float(steps), 0.5f);
        if (shaping) s.features |= cloudHeightShaping;
        return alphaAt(run(s, w, h, constant), w / 2, h / 2);
    };
    // One sample: density a at the bottom face (factor 1), a / 2 at the top face (factor 0.5).
    EXPECT_NEAR(opacity(lookingUp(), 1, true), 0.3f * a, kTolerance);
    EXPECT_NEAR(opacity(lookingDown(), 1, true), 0.3f * a * 0.5f, kTolerance);
    EXPECT_NEAR(opacity(lookingDown(), 1, false), 0.3f * a, kTolerance);  // the factor is the feature's
    // Two samples from the top: y = 2 (factor 0.5) and y = 1, the middle (factor 0.75).
    const float first = 0.3f * a * 0.5f, second = 0.3f * a * 0.75f;
    EXPECT_NEAR(opacity(lookingDown(), 2, true), first + second * (1.0f - first), kTolerance);
}

TEST_F(CloudsOnGl, TheThresholdRemapsClampOfDensityMinusThresholdOverOneMinusThreshold) {
    const int w = 9, h = 9;
    CloudDensityTexture mid = CloudDensityTexture::fromImage(constantDensity(160));
    const float density = 2.0f * srgbDecode(160.0f / 255.0f);  // two layers: about 0.70
    for (float threshold : {0.0f, 0.3f, 0.5f, 0.69f, 0.8f}) {
        CloudFrameSettings s = marchSettings(lookingUp(), w, h);
        s.march = cloudMarch(0.0f, 2.0f, 1.0f, threshold);
        s.features |= cloudThreshold;
        const float remapped = std::clamp(density - threshold, 0.0f, 1.0f) / (1.0f - threshold);
        EXPECT_NEAR(alphaAt(run(s, w, h, mid), w / 2, h / 2), 0.3f * remapped, kTolerance)
            << "threshold " << threshold;
    }
}

TEST_F(CloudsOnGl, TheObjectShadowDarkensByHalfOfMinSOneAndOffTheMapCountsAsLit) {
    const int w = 9, h = 9;
    auto lightAt = [&](const Camera& cam, int steps, const CloudDensityTexture& density) {
        CloudFrameSettings s = marchSettings(cam, w, h);
        s.march = cloudMarch(0.0f, 2.0f, float(steps), 0.5f);
        s.features |= cloudShadows;
        FloatImage out = runUnderTheSun(s, w, h, density);
        // Straight alpha over black: rgb / alpha is the colour (1) times 1 - shadow.
        return out.texel(w / 2, h / 2, 0) / std::max(alphaAt(out, w / 2, h / 2), 1e-6f);
    };
    const Camera abovePillar = cameraAt({kPillar.x, 12.0f, kPillar.z}, 0, -89.9f);
    // One sample in the pillar's shadow: S = 0.3 (s = 1, T = 1), so 1 - 0.5 x 0.3.
    EXPECT_NEAR(lightAt(abovePillar, 1, constant), 1.0f - 0.5f * 0.3f, 5e-3f);
    // Eight thin samples in shadow: S = 0.3 x (sum of T) is about 2.3, capped at 1: half the light.
    CloudDensityTexture thin = CloudDensityTexture::fromImage(constantDensity(40));
    EXPECT_NEAR(lightAt(abovePillar, 8, thin), 0.5f, 5e-3f);
    // 400 m away from everything the map was fitted to: outside it, so lit.
    EXPECT_NEAR(lightAt(cameraAt({400.0f, 12.0f, 400.0f}, 0, -89.9f), 8, thin), 1.0f, 1e-3f);
}

class CloudDrift : public CloudsWithTheGeneratedTexture {
protected:
    void SetUp() override {
        CloudsWithTheGeneratedTexture::SetUp();
        auto scene = lessonScene();
        ASSERT_TRUE(scene.ok());
        ASSERT_FALSE(scene->clouds.empty());
        layer = scene->clouds.front();
    }
    // One layer of the texture at `scale`, scrolled by `offset`, seen from a camera at (x, 5, z).
    FloatImage view(float scale, glm::vec2 offset, float x, float z) {
        CloudFrameSettings s = marchSettings(cameraAt({x, 5, z}, 30, -30), kW, kH);
        s.features &= ~cloudTwoScales;
        s.scales = {scale, scale};
        s.scrollOffset = glm::vec4(offset, 0.0f, 0.0f);
        return run(s, kW, kH, texture);
    }
    static constexpr int kW = 32, kH = 20;
    CloudLayer layer;
};

TEST_F(CloudDrift, EachLayerDriftsAtMinusSpeedOverScale) {
    const glm::vec2 expected[2] = {{0.59f, 1.28f}, {0.34f, 0.17f}};  // the chapter's m/s in (x, z)
    for (int l = 0; l < 2; ++l) {
        const float scale = layer.noise[std::size_t(l)].scale;
        const glm::vec2 speed = layer.noise[std::size_t(l)].scroll;
        const glm::vec2 drift = -speed / scale;
        EXPECT_NEAR(drift.x, expected[l].x, 0.005f) << "layer " << l;
        EXPECT_NEAR(drift.y, expected[l].y, 0.005f) << "layer " << l;
        // After 20 s the clouds are where they were, moved by drift x 20 s: a camera moved with them
        // sees the first picture again; one left behind does not.
        const double seconds = 20.0;
        CloudScroll later = CloudScroll::at({0.0, 0.0, 0.0, 0.0}, {speed.x, speed.y, 0.0, 0.0}, seconds);
        FloatImage start = view(scale, {0, 0}, 0, 0);
        const glm::vec2 moved = drift * float(seconds);
        FloatImage along = view(scale, glm::vec2(later.offset()), moved.x, moved.y);
        FloatImage behind = view(scale, glm::vec2(later.offset()), 0, 0);
        ASSERT_TRUE(allFinite(along));
        double same = meanAbsoluteAlphaDifference(start, along),
               apart = meanAbsoluteAlphaDifference(start, behind);
        std::printf("layer %d: moved with the drift %g, left behind %g\n", l, same, apart);
        EXPECT_LT(same, 2e-3) << "layer " << l;
        EXPECT_GT(apart, 10.0 * same) << "layer " << l;
    }
}

TEST_F(CloudDrift, TheTwoScalesRepeatTogetherEvery39497Metres) {
    EXPECT_EQ(std::lcm(311, 127), 39497);
    const float s0 = layer.noise[0].scale, s1 = layer.noise[1].scale;
    EXPECT_NEAR(1.0f / s0, 311.0f, 0.01f);
    EXPECT_NEAR(1.0f / s1, 127.0f, 0.01f);
    const int w = kW, h = kH;
    auto both = [&](float x) {
        CloudFrameSettings s = marchSettings(cameraAt({x, 5, x}, 30, -30), w, h);
        s.scales = {s0, s1};
        return run(s, w, h, texture);
    };
    FloatImage home = both(0.0f);
    double period = meanAbsoluteAlphaDifference(home, both(39497.0f));
    double half = meanAbsoluteAlphaDifference(home, both(39497.0f / 2.0f));
    double oneLayer = meanAbsoluteAlphaDifference(home, both(311.0f));  // layer 0 repeats, layer 1 does not
    std::printf("39497 m: %g, half of it: %g, 311 m: %g\n", period, half, oneLayer);
    // What is left at 39.5 km is the camera's own float position (a spacing of 4 mm there).
    EXPECT_LT(period, 0.01);
    EXPECT_GT(half, 20.0 * period);
    EXPECT_GT(oneLayer, 20.0 * period);  // one layer's repeat alone is not the pattern's
}

}  // namespace
