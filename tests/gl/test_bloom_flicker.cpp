// Lesson 06: fireflies. A small, very bright dot moving by fractions of a texel is drawn as a scene
// rasteriser draws it (point-sampled at pixel centres), so it covers 0, 1 or 2 pixels from frame to
// frame. The Bloom chapter blooms every covered pixel in proportion to its value, so the glow's energy
// jumps with the coverage; the Karis average on the first downsample (step 5) weights each tap by
// 1 / (1 + luma), so a lone bright texel can no longer outweigh its neighbours and the glow steadies.
// Also: effects/bloom/bloom_flicker.hpp measures what this test measures, on GL.
#include <algorithm>
#include <cmath>
#include <vector>

#include "effects/bloom/bloom_flicker.hpp"
#include "gl_test.hpp"
#include "test_bloom_harness.hpp"

using namespace fx;
using namespace fx::test;

namespace {

class BloomFlickerTest : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        ASSERT_TRUE(programsBuilt());
    }
    BloomEffects effects;
};

constexpr int kWidth = 128, kHeight = 64;  // the Bloom chapter's first level: 64x32
constexpr int kFrames = 16;

// Frame t: a dim floor (0.05), a steady lamp (4, 3.5, 3) of 12x12 pixels, and a dot of radius 0.6
// pixels and value 500 that moves 0.3 pixels right and 0.13 up per frame: it covers the pixel
// centres within its radius, as rasterisation does.
FloatImage frameWithDot(int t) {
    const float cx = 80.2f + 0.3f * float(t), cy = 30.1f + 0.13f * float(t), r = 0.6f;
    return makeImage(kWidth, kHeight, [=](int x, int y) {
        float dx = float(x) + 0.5f - cx, dy = float(y) + 0.5f - cy;
        if (dx * dx + dy * dy <= r * r) return std::array<float, 4>{500.0f, 450.0f, 400.0f, 1.0f};
        if (x >= 20 && x < 32 && y >= 26 && y < 38) return std::array<float, 4>{4.0f, 3.5f, 3.0f, 1.0f};
        return std::array<float, 4>{0.05f, 0.05f, 0.05f, 1.0f};
    });
}

double lumaSum(const FloatImage& image) {
    double sum = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            sum +=
                0.2126 * image.texel(x, y, 0) + 0.7152 * image.texel(x, y, 1) + 0.0722 * image.texel(x, y, 2);
    return sum;
}

// The mean frame-to-frame change of the glow's energy (bloom.up[0], summed), relative to its mean.
double relativeFlicker(const std::vector<double>& energy) {
    double change = 0, mean = 0;
    for (std::size_t t = 0; t < energy.size(); ++t) {
        mean += energy[t] / double(energy.size());
        if (t > 0) change += std::abs(energy[t] - energy[t - 1]) / double(energy.size() - 1);
    }
    return mean > 0 ? change / mean : 0.0;
}

}  // namespace

TEST_F(BloomFlickerTest, KarisAverageSteadiesAMovingFirefly) {
    EffectRunner runner(kWidth, kHeight);
    BloomChainSettings plain = bloomChapterChain(1.0f, 6);
    BloomChainSettings karis = plain;
    karis.karisAverage = true;
    std::vector<double> withoutKaris, withKaris;
    int coverageChanges = 0;
    double lastCoverage = -1;
    for (int t = 0; t < kFrames; ++t) {
        FloatImage input = frameWithDot(t);
        double coverage = 0;
        for (float v : input.texels) coverage += v == 500.0f ? 1 : 0;
        coverageChanges += t > 0 && coverage != lastCoverage ? 1 : 0;
        lastCoverage = coverage;
        FloatImage a = runBloom(runner, effects, input, TextureFormat::RGBA16F, plain, 2.0f, "glow");
        ASSERT_FALSE(a.empty()) << runner.lastError;
        FloatImage b = runBloom(runner, effects, input, TextureFormat::RGBA16F, karis, 2.0f, "glow");
        ASSERT_FALSE(b.empty()) << runner.lastError;
        withoutKaris.push_back(lumaSum(a));
        withKaris.push_back(lumaSum(b));
    }
    // The dot does cover a varying number of pixels: the input flickers, as a rasterised firefly does.
    ASSERT_GE(coverageChanges, 4);
    double plainFlicker = relativeFlicker(withoutKaris), karisFlicker = relativeFlicker(withKaris);
    RecordProperty("flicker_without_karis_percent", std::to_string(100 * plainFlicker));
    RecordProperty("flicker_with_karis_percent", std::to_string(100 * karisFlicker));
    std::printf("glow energy change per frame: without Karis %.3f %%, with Karis %.3f %% (ratio %.1f)\n",
                100 * plainFlicker, 100 * karisFlicker, plainFlicker / std::max(karisFlicker, 1e-12));
    // The lamp alone is steady, so with the firefly tamed the glow changes by well under 1 % a frame;
    // without Karis the firefly's coverage swings it by tens of per cent.
    EXPECT_GT(plainFlicker, 0.10);
    EXPECT_LT(karisFlicker, 0.01);
    EXPECT_GT(plainFlicker, 10.0 * karisFlicker);
}

TEST_F(BloomFlickerTest, FlickerPassWritesTheChangeAndMeasuresTheEnergy) {
    // Two frames through BloomFlicker: bloom.flicker is |glow(1) - glow(0)| texel by texel, and the
    // change in per cent matches the glow's summed energy read back here (64x32: the 1x1 mip is the
    // exact mean).
    EffectRunner runner(kWidth, kHeight);
    BloomFlicker flicker;
    ASSERT_TRUE(programsBuilt());
    BloomChainSettings plain = bloomChapterChain(1.0f, 6);
    // Two frames in which the dot covers a different number of pixels, so the glow really changes.
    auto covered = [](const FloatImage& image) {
        return std::count(image.texels.begin(), image.texels.end(), 500.0f);
    };
    int second = 1;
    while (second < 16 && covered(frameWithDot(second)) == covered(frameWithDot(0))) ++second;
    ASSERT_LT(second, 16) << "the dot never changes its coverage";
    std::vector<FloatImage> glows;
    FloatImage change;
    for (int t = 0; t < 2; ++t) {
        FloatImage input = frameWithDot(t * second);
        glows.push_back(runBloom(runner, effects, input, TextureFormat::RGBA16F, plain, 2.0f, "glow"));
        change = runner.run(input, TextureFormat::RGBA16F, [&](FrameGraph& g, TextureHandle in) {
            BloomChain::Declared d = effects.chain.declare(g, in, plain);
            return flicker.declare(g, d.glow(), d.levels.front().size, t == 0).output;
        });
        ASSERT_FALSE(change.empty()) << runner.lastError;
        EXPECT_EQ(flicker.stats().measured, t == 1);
    }
    ASSERT_EQ(change.width, 64);
    ASSERT_EQ(change.height, 32);
    float worst = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x)
            for (int c = 0; c < 3; ++c) {
                float expected = std::abs(glows[1].texel(x, y, c) - glows[0].texel(x, y, c));
                worst = std::max(worst, std::abs(change.texel(x, y, c) - expected) / (expected + 0.01f));
            }
    EXPECT_LT(worst, 0.01f);  // bloom.flicker is stored as a half float
    double e0 = lumaSum(glows[0]), e1 = lumaSum(glows[1]);
    double expectedPercent = 100.0 * std::abs(e1 - e0) / std::max(e0, e1);
    EXPECT_GT(expectedPercent, 1.0);
    EXPECT_NEAR(flicker.stats().changePercent, expectedPercent, 0.02 * expectedPercent + 0.01);
    EXPECT_NEAR(flicker.stats().meanGlow, e1 / (64.0 * 32.0), 1e-3 * e1 / (64.0 * 32.0));
}
