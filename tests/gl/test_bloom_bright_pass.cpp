// Bloom (lesson 06): the bright pass on coloured input, read back as floats. Grey input cannot tell the
// chapters' hue-preserving ratio from a per-channel subtraction, nor the brightest channel from
// luminance; these vectors can (Shader effects §3.7.1 and its test table, Bloom §1.5 and hard cases 5
// and 6).
#include <algorithm>
#include <cmath>

#include "gl_test.hpp"
#include "test_bloom_harness.hpp"

using namespace fx;
using namespace fx::test;

namespace {

using Rgb = std::array<float, 3>;

class BloomBrightPass : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        ASSERT_TRUE(programsBuilt());
    }

    // What the bright pass writes into bloom.down[0] for a uniform colour c (alpha 1). Every tap of a
    // uniform image reads c, so each texel is the formula applied to c once. The level is 32-bit float,
    // so nothing rounds the answer.
    FloatImage brightPass(BloomChainSettings settings, Rgb c) {
        settings.format = TextureFormat::RGBA32F;
        FloatImage input = makeImage(kWidth, kHeight, [c](int, int) {
            return std::array<float, 4>{c[0], c[1], c[2], 1.0f};
        });
        return runChain(runner, effects, input, TextureFormat::RGBA32F, settings,
                        [](const BloomChain::Declared& d) { return d.down[0]; });
    }

    static constexpr int kWidth = 32, kHeight = 16;
    BloomEffects effects;
    EffectRunner runner{kWidth, kHeight};
};

// Every texel's RGB is `expected` within `tolerance` (absolute).
::testing::AssertionResult everyTexelIs(const FloatImage& image, Rgb expected, float tolerance = 1e-4f) {
    if (image.empty()) return ::testing::AssertionFailure() << "nothing was read back";
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) {
                float v = image.texel(x, y, c);
                if (!(std::abs(v - expected[std::size_t(c)]) <= tolerance))
                    return ::testing::AssertionFailure()
                           << "texel (" << x << ", " << y << ") channel " << c << " is " << v << ", expected "
                           << expected[std::size_t(c)];
            }
    return ::testing::AssertionSuccess();
}

// The quadratic soft knee (beyond the chapters; effects.md's "quadratic soft-knee threshold"), as a
// function of the brightest channel b: 0 up to t - k, the chapters' b - t from t + k on, and between
// them the parabola that meets both with the same slope.
float kneeAmount(float b, float threshold, float k) {
    if (b <= threshold - k) return 0.0f;
    if (b >= threshold + k) return b - threshold;
    float s = b - threshold + k;
    return s * s / (4.0f * k);
}

}  // namespace

TEST_F(BloomBrightPass, ShaderEffectsHighPassScalesEveryChannelByTheBrightestChannelsRatio) {
    // The first chapter's test table, threshold 1, intensity 2: (2, 1, 0) has ratio 1/2, so E x 2 is
    // (2, 1, 0) again; (3, 0.8, 0.2) has ratio 2/3: E = (2, 0.5333, 0.1333), x 2 = (4, 1.0667, 0.2667).
    // Subtracting the threshold per channel would give (2, 0, 0) and (4, 0, 0).
    BloomChainSettings s = shaderEffectsChain(1.0f, 2.0f, 1);
    EXPECT_TRUE(everyTexelIs(brightPass(s, {2.0f, 1.0f, 0.0f}), {2.0f, 1.0f, 0.0f})) << runner.lastError;
    EXPECT_TRUE(everyTexelIs(brightPass(s, {3.0f, 0.8f, 0.2f}), {4.0f, 3.2f / 3.0f, 0.8f / 3.0f}));
}

TEST_F(BloomBrightPass, BloomChapterBrightPassKeepsTheHue) {
    // The Bloom chapter's worked example: orange (2, 0.5, 0) has brightness 2, ratio 0.5, and keeps its
    // green: (1, 0.25, 0), where per-channel subtraction loses it: (1, 0, 0). The first chapter's
    // (3, 0.8, 0.2) gives the same E with this chain's filters: (2, 0.5333, 0.1333).
    BloomChainSettings s = bloomChapterChain(1.0f, 1);
    EXPECT_TRUE(everyTexelIs(brightPass(s, {2.0f, 0.5f, 0.0f}), {1.0f, 0.25f, 0.0f})) << runner.lastError;
    EXPECT_TRUE(everyTexelIs(brightPass(s, {3.0f, 0.8f, 0.2f}), {2.0f, 1.6f / 3.0f, 0.4f / 3.0f}));
}

TEST_F(BloomBrightPass, SaturatedBlueBloomsWhileGreyBelowTheThresholdDoesNot) {
    // Bloom, hard case 6: brightness is the largest channel, not luminance. Pure blue (0, 0, 1.2) has a
    // Rec.709 luminance of 0.09 but passes the threshold 1 by 0.2; grey 0.9 (luminance 0.9) does not.
    for (BloomChainSettings s : {shaderEffectsChain(1.0f, 2.0f, 1), bloomChapterChain(1.0f, 1)}) {
        float intensity = s.extractScale;
        EXPECT_TRUE(everyTexelIs(brightPass(s, {0.0f, 0.0f, 1.2f}), {0.0f, 0.0f, 0.2f * intensity}))
            << runner.lastError;
        EXPECT_TRUE(everyTexelIs(brightPass(s, {0.9f, 0.9f, 0.9f}), {0.0f, 0.0f, 0.0f}));
    }
}

TEST_F(BloomBrightPass, ThresholdZeroKeepsTheWholeColourAndBlackStaysBlack) {
    // With threshold 0 the ratio is b / b = 1: every colour passes unchanged (0 is not "off"). Black has
    // b = 0 and must come out 0. A knee is a fraction of the threshold, so with threshold 0 it changes
    // nothing either (an absolute knee of 0.5 would lift (0.3, 0.1, 0.05)).
    for (float knee : {0.0f, 0.5f}) {
        BloomChainSettings s = bloomChapterChain(0.0f, 1);
        s.knee = knee;
        EXPECT_TRUE(everyTexelIs(brightPass(s, {2.0f, 0.5f, 0.0f}), {2.0f, 0.5f, 0.0f})) << runner.lastError;
        EXPECT_TRUE(everyTexelIs(brightPass(s, {0.3f, 0.1f, 0.05f}), {0.3f, 0.1f, 0.05f})) << "knee " << knee;
        EXPECT_TRUE(everyTexelIs(brightPass(s, {0.0f, 0.0f, 0.0f}), {0.0f, 0.0f, 0.0f})) << "knee " << knee;
    }
}

TEST_F(BloomBrightPass, HardCutIsContinuousAtTheThreshold) {
    // Bloom, hard case 5: just above the threshold the ratio is about 0, so a surface that brightens
    // past it fades in from nothing (there is a kink in the slope, no jump in the value).
    BloomChainSettings s = bloomChapterChain(1.0f, 1);
    EXPECT_TRUE(everyTexelIs(brightPass(s, {1.0f, 0.5f, 0.0f}), {0.0f, 0.0f, 0.0f})) << runner.lastError;
    EXPECT_TRUE(everyTexelIs(brightPass(s, {1.001f, 0.5f, 0.0f}), {0.001f, 0.0005f / 1.001f, 0.0f}, 1e-5f));
}

TEST_F(BloomBrightPass, SoftKneeMeetsTheHardCutWithoutAJumpAndKeepsTheHue) {
    // Knee 0.5 of threshold 1: the parabola runs from b = 0.5 to 1.5, where it joins b - 1. Swept across
    // that range in steps of 0.02 with an orange (b, b/2, b/4), the amount follows the knee, moves at
    // most one step per step (the slope never exceeds the hard cut's 1: no jump anywhere, the threshold
    // included), and the other channels keep their proportion to red.
    BloomChainSettings s = bloomChapterChain(1.0f, 1);
    s.knee = 0.5f;
    const float k = s.knee * s.threshold, step = 0.02f;
    float previous = 0.0f;
    for (int i = 0; i <= 70; ++i) {
        float b = 0.3f + step * float(i);
        FloatImage out = brightPass(s, {b, 0.5f * b, 0.25f * b});
        ASSERT_FALSE(out.empty()) << runner.lastError;
        float amount = kneeAmount(b, s.threshold, k);
        EXPECT_TRUE(everyTexelIs(out, {amount, 0.5f * amount, 0.25f * amount})) << "b = " << b;
        float red = out.texel(4, 4, 0);
        if (i > 0) {
            EXPECT_LE(std::abs(red - previous), step + 1e-4f) << "a jump at b = " << b;
        }
        previous = red;
    }
    // At the threshold itself the knee already lets a quarter of k through, where the hard cut gives 0.
    EXPECT_TRUE(everyTexelIs(brightPass(s, {1.0f, 0.5f, 0.25f}), {k / 4, k / 8, k / 16}));
}

TEST_F(BloomBrightPass, ColouredAreaComesBackWithItsHueThroughTheWholeChain) {
    // The Bloom chapter's chain adds the bright part 6 times and the composite doubles it: a uniform
    // orange (2, 0.5, 0) becomes (2, 0.5, 0) + 12 (1, 0.25, 0) = (14, 3.5, 0). With per-channel
    // subtraction it would come back (14, 0.5, 0): a red glow around an orange light.
    EffectRunner big(128, 64);
    FloatImage in = makeImage(128, 64, [](int, int) { return std::array<float, 4>{2.0f, 0.5f, 0.0f, 1.0f}; });
    FloatImage out = runBloom(big, effects, in, TextureFormat::RGBA16F, bloomChapterChain(1.0f, 6), 2.0f);
    EXPECT_TRUE(everyTexelIs(out, {14.0f, 3.5f, 0.0f}, 14.0f * 0.005f)) << big.lastError;
    // The reference Gaussian glow shares the bright pass: 4 levels at weight 1/4 add E once.
    FloatImage ref = runReference(big, effects, in, beyondChapters(4), {128, 64}, 0.25f);
    EXPECT_TRUE(everyTexelIs(ref, {3.0f, 0.75f, 0.0f}, 1e-3f)) << big.lastError;
}

TEST_F(BloomBrightPass, ANegativeThresholdBloomsAsThresholdZeroWithoutNanOrNegativeLight) {
    // Shader effects, hard case 9, clamped in the effect (bloom_common.glsl), not only by lesson 06's
    // slider: a scene file or another caller can still pass -1. Unclamped, (b + 1) / b scales
    // (0.3, 0.1, 0.05) to (1.3, 0.43, 0.22) and a near-black 1e-4 to about 1: every pixel blooms, the
    // darkest most. Clamped, each chain's bright pass and lesson 06 step 3's whole chain give what
    // threshold 0 gives: finite, never negative.
    const Rgb colours[] = {{0.0f, 0.0f, 0.0f}, {1e-4f, 0.0f, 0.0f}, {0.3f, 0.1f, 0.05f}, {2.0f, 0.5f, 0.0f}};
    BloomChainSettings knee = bloomChapterChain(-1.0f, 1);
    knee.knee = 0.5f;
    for (BloomChainSettings s : {shaderEffectsChain(-1.0f, 2.0f, 1), bloomChapterChain(-1.0f, 1), knee}) {
        for (const Rgb& c : colours) {
            Rgb expected = {c[0] * s.extractScale, c[1] * s.extractScale, c[2] * s.extractScale};
            EXPECT_TRUE(everyTexelIs(brightPass(s, c), expected, 1e-4f * s.extractScale))
                << "threshold -1, colour (" << c[0] << ", " << c[1] << ", " << c[2] << ")"
                << runner.lastError;
        }
    }

    // Step 3's chain and composite over a ramp from black to 4: the same picture as at threshold 0.
    EffectRunner big(128, 64);
    FloatImage ramp = makeImage(128, 64, [](int x, int y) {
        float v = (y < 32 ? 1e-3f : 4.0f / 127.0f) * float(x);
        return std::array<float, 4>{v, 0.5f * v, 0.25f * v, 1.0f};
    });
    auto stepThree = [&](float threshold) {
        return runBloom(big, effects, ramp, TextureFormat::RGBA16F, shaderEffectsChain(threshold, 2.0f, 6),
                        averagedCompositeScale(6));
    };
    FloatImage negative = stepThree(-1.0f), zero = stepThree(0.0f);
    ASSERT_FALSE(negative.empty()) << big.lastError;
    ASSERT_EQ(negative.texels.size(), zero.texels.size());
    EXPECT_TRUE(allFinite(negative));
    float lowest = 0.0f, worst = 0.0f;
    for (std::size_t i = 0; i < negative.texels.size(); ++i) {
        lowest = std::min(lowest, negative.texels[i]);
        worst = std::max(worst, std::abs(negative.texels[i] - zero.texels[i]));
    }
    EXPECT_GE(lowest, 0.0f) << "negative light";
    EXPECT_LE(worst, 1e-3f) << "threshold -1 differs from threshold 0";
}
