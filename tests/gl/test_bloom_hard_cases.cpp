// Bloom (lesson 06): the Bloom and Shader effects chapters' hard cases, read back as floats. Values
// above a half float's range, Inf and NaN in the scene; sums that overflow only once the levels are
// added; negative colours; window sizes where levels would be smaller than a texel.
#include <cmath>

#include "effects/bloom/bloom_levels.hpp"
#include "gl_test.hpp"
#include "test_bloom_harness.hpp"

using namespace fx;
using namespace fx::test;

namespace {

class BloomHardCases : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        ASSERT_TRUE(programsBuilt());
    }
    BloomEffects effects;
};

struct Chain {
    const char* name;
    BloomChainSettings settings;
    float scale;
};

// The three chains of lesson 06 (steps 3, 4 and 5), with the composites they use.
std::vector<Chain> lessonChains() {
    BloomChainSettings beyond = beyondChapters(6);
    beyond.knee = 0.5f;
    return {{"Shader effects", shaderEffectsChain(1.0f, 2.0f, 6), averagedCompositeScale(6)},
            {"Bloom chapter", bloomChapterChain(1.0f, 6), 2.0f},
            {"beyond", beyond, normalisedCompositeScale(2.0f, 6)}};
}

// A dim scene (0.2) with a bright patch (6, 3, 1) on the left half, and `special` planted at texel (x, y).
FloatImage sceneWith(int width, int height, int x0, int y0, std::array<float, 4> special) {
    return makeImage(width, height, [=](int x, int y) {
        if (x == x0 && y == y0) return special;
        bool bright = x > width / 8 && x < width / 2 && y > height / 4 && y < 3 * height / 4;
        return bright ? std::array<float, 4>{6.0f, 3.0f, 1.0f, 1.0f}
                      : std::array<float, 4>{0.2f, 0.2f, 0.2f, 1.0f};
    });
}

// The largest difference of a from b relative to b (plus 0.01 for dark pixels), outside the square of
// `radius` around (cx, cy).
float worstRelativeDifference(const FloatImage& a, const FloatImage& b, int cx, int cy, int radius) {
    float worst = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            if (std::abs(x - cx) <= radius && std::abs(y - cy) <= radius) continue;
            for (int c = 0; c < 3; ++c) {
                float d =
                    std::abs(a.texel(x, y, c) - b.texel(x, y, c)) / (std::abs(b.texel(x, y, c)) + 0.01f);
                worst = std::max(worst, d);
            }
        }
    return worst;
}

}  // namespace

TEST_F(BloomHardCases, ValuesAboveHalfFloatRangeInfAndNanStayFinite) {
    // 1e6 is stored as +Inf in the RGBA16F scene (Bloom, hard case 1); the Inf and NaN texels are
    // planted in the bright patch, where an unguarded bright pass computes (Inf - 1) / Inf = NaN.
    const int w = 160, h = 96;
    EffectRunner runner(w, h);
    const float nan = std::nanf(""), inf = INFINITY;
    for (const Chain& chain : lessonChains()) {
        for (auto special :
             {std::array<float, 4>{1e6f, 1e6f, 1e6f, 1.0f}, std::array<float, 4>{inf, 2.0f, 1.0f, 1.0f},
              std::array<float, 4>{nan, nan, nan, 1.0f}, std::array<float, 4>{2.0f, -inf, nan, 1.0f}}) {
            FloatImage input = sceneWith(w, h, 50, 48, special);
            FloatImage glow =
                runBloom(runner, effects, input, TextureFormat::RGBA16F, chain.settings, chain.scale, "glow");
            ASSERT_FALSE(glow.empty()) << runner.lastError;
            EXPECT_TRUE(allFinite(glow)) << chain.name << ": a level holds a NaN or an Inf";
            FloatImage out =
                runBloom(runner, effects, input, TextureFormat::RGBA16F, chain.settings, chain.scale);
            EXPECT_TRUE(allFinite(out)) << chain.name << ": bloom.result holds a NaN or an Inf";
            for (float v : out.texels) EXPECT_LE(v, kBloomMaxValue);
        }
    }
}

TEST_F(BloomHardCases, OneNanTexelDoesNotSpreadOverTheScreen) {
    // Unguarded, one NaN texel reaches every level and comes back as a block the size of the smallest
    // level's texel (64x64 pixels). Guarded, the tap that holds it reads 0: the glow differs from the
    // same scene with that texel at 0 by a small dent, and the screen away from it not at all beyond
    // a fraction of the glow.
    const int w = 256, h = 128;
    EffectRunner runner(w, h);
    for (const Chain& chain : lessonChains()) {
        FloatImage withNan = runBloom(runner, effects, sceneWith(w, h, 80, 64, {NAN, NAN, NAN, 1.0f}),
                                      TextureFormat::RGBA16F, chain.settings, chain.scale);
        ASSERT_FALSE(withNan.empty()) << runner.lastError;
        FloatImage withZero = runBloom(runner, effects, sceneWith(w, h, 80, 64, {0.0f, 0.0f, 0.0f, 1.0f}),
                                       TextureFormat::RGBA16F, chain.settings, chain.scale);
        ASSERT_TRUE(allFinite(withNan)) << chain.name;
        // The NaN's tap reads 0 where the zero texel's tap reads three bright texels and a dark one: a
        // dent of a few per cent next to it, well under 1 % of the glow farther than 8 pixels away.
        EXPECT_LT(worstRelativeDifference(withNan, withZero, 80, 64, 0), 0.08f) << chain.name;
        EXPECT_LT(worstRelativeDifference(withNan, withZero, 80, 64, 8), 0.01f) << chain.name;
    }
}

TEST_F(BloomHardCases, AccumulationThatWouldOverflowIsClampedFirst) {
    // 30000 is a finite half float, and its bright part alone is too. The Bloom chapter adds 6 levels
    // and doubles them: 30000 + 12 * 29999 would be infinite in a half float (Bloom, hard case 2).
    // The bright pass keeps at most kBloomMaxBright and every sum stays below kBloomMaxValue.
    EffectRunner runner(128, 64);
    for (TextureFormat format : {TextureFormat::RGBA16F, TextureFormat::R11F_G11F_B10F}) {
        BloomChainSettings s = bloomChapterChain(1.0f, 8);
        s.format = format;
        FloatImage in = uniformGrey(128, 64, 30000.0f);
        FloatImage glow = runBloom(runner, effects, in, TextureFormat::RGBA16F, s, 4.0f, "glow");
        ASSERT_FALSE(glow.empty()) << runner.lastError;
        ASSERT_TRUE(allFinite(glow)) << toString(format);
        // Six levels exist at 128x64 (64x32 .. 2x1), each holding the capped bright part.
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(glow.texel(10, 10, c), 6 * kBloomMaxBright, 6 * kBloomMaxBright * 0.01);
        FloatImage out = runBloom(runner, effects, in, TextureFormat::RGBA16F, s, 4.0f);
        ASSERT_TRUE(allFinite(out)) << toString(format);
        for (float v : out.texels) EXPECT_LE(v, kBloomMaxValue);
        // 30000 + 4 * 6144 = 54576: below the cap, so the composite's arithmetic is still exact.
        EXPECT_NEAR(out.texel(64, 32, 0), 30000.0f + 4.0f * 6.0f * kBloomMaxBright, 60.0f);
    }
}

TEST_F(BloomHardCases, NegativeColoursMakeNoNegativeHalo) {
    // A texel (8, -3, 0) passes the threshold by its red; the ratio would scale its -3 too and paint a
    // dark halo (Bloom chapter, hard case 4). A region of -50 must not darken its neighbours either.
    const int w = 128, h = 64;
    EffectRunner runner(w, h);
    FloatImage input = makeImage(w, h, [](int x, int y) {
        if (x >= 20 && x < 40 && y >= 20 && y < 40) return std::array<float, 4>{8.0f, -3.0f, 0.0f, 1.0f};
        if (x >= 70 && x < 90 && y >= 20 && y < 40) return std::array<float, 4>{-50.0f, -50.0f, -50.0f, 1.0f};
        return std::array<float, 4>{0.1f, 0.1f, 0.1f, 1.0f};
    });
    for (const Chain& chain : lessonChains()) {
        FloatImage glow =
            runBloom(runner, effects, input, TextureFormat::RGBA16F, chain.settings, chain.scale, "glow");
        ASSERT_FALSE(glow.empty()) << runner.lastError;
        float lowest = 0;
        for (float v : glow.texels) lowest = std::min(lowest, v);
        EXPECT_GE(lowest, 0.0f) << chain.name << ": the chain holds negative light";
        FloatImage out =
            runBloom(runner, effects, input, TextureFormat::RGBA16F, chain.settings, chain.scale);
        float darkest = 0;
        for (std::size_t i = 0; i < out.texels.size(); ++i)
            darkest = std::min(darkest, out.texels[i] - runner.storedInput.texels[i]);
        EXPECT_GE(darkest, -1e-3f) << chain.name << ": bloom darkened a pixel";
        // The red glow is there: the positive part still blooms.
        EXPECT_GT(out.texel(45, 30, 0) - runner.storedInput.texel(45, 30, 0), 0.05f) << chain.name;
    }
}

TEST_F(BloomHardCases, OddAndTinySizesMakeOnlyLevelsOfAtLeastOneTexel) {
    // 1x1, 63x63, 1279x719: no incomplete framebuffer, no texture of size 0, no GL error (the fixture
    // fails on any), every level as bloomLevels says, and a finite result.
    for (Size2D size : {Size2D{1, 1}, Size2D{3, 2}, Size2D{63, 63}, Size2D{1279, 719}}) {
        EffectRunner runner(size.width, size.height);
        for (const Chain& chain : lessonChains()) {
            int made = -1;
            FloatImage out = runBloom(runner, effects, uniformGrey(size.width, size.height, 5.0f),
                                      TextureFormat::RGBA16F, chain.settings, chain.scale, "result", &made);
            ASSERT_TRUE(runner.lastError.empty()) << runner.lastError;
            std::vector<BloomLevel> expected =
                bloomLevels(size, firstLevelDivisor(chain.settings.filters), 6);
            EXPECT_EQ(made, int(expected.size())) << chain.name << " at " << size.width << "x" << size.height;
            for (const TextureRecord& t : runner.report.textures) {
                if (t.name.rfind("bloom.", 0) != 0) continue;
                EXPECT_GE(t.spec.width, 1) << t.name;
                EXPECT_GE(t.spec.height, 1) << t.name;
            }
            if (made > 0) {
                ASSERT_FALSE(out.empty());
                EXPECT_TRUE(allFinite(out)) << chain.name;
            }
        }
        // The reference too (its full-resolution Gaussians are slow at 1279x719; the small sizes are
        // the ones that can go wrong).
        if (size.width > 100) continue;
        FloatImage ref = runReference(runner, effects, uniformGrey(size.width, size.height, 5.0f),
                                      beyondChapters(6), size, 0.5f);
        EXPECT_TRUE(runner.lastError.empty()) << runner.lastError;
        EXPECT_TRUE(allFinite(ref));
    }
}

TEST_F(BloomHardCases, BrightEdgeColumnDoesNotWrapRoundToTheOppositeEdge) {
    // Bloom, hard case 11: the taps reach past the border, and REPEAT would fetch the opposite edge
    // there. A bright column at the left edge of a dark scene then lights the right edge as brightly as
    // its own neighbours. With CLAMP_TO_EDGE the right edge gets only what the coarsest levels carry
    // across the whole width: far less than the column's neighbour two pixels away.
    const int w = 512, h = 64;
    EffectRunner runner(w, h);
    FloatImage input = makeImage(w, h, [](int x, int) {
        float v = x < 2 ? 20.0f : 0.0f;
        return std::array<float, 4>{v, v, v, 1.0f};
    });
    for (const Chain& chain : lessonChains()) {
        FloatImage out =
            runBloom(runner, effects, input, TextureFormat::RGBA16F, chain.settings, chain.scale);
        ASSERT_FALSE(out.empty()) << runner.lastError;
        for (int y : {0, h / 2, h - 1}) {
            float near = out.texel(3, y, 0), farEdge = out.texel(w - 1, y, 0);
            ASSERT_GT(near, 0.0f) << chain.name;
            EXPECT_LT(farEdge, 0.01f * near) << chain.name << ", row " << y << ": light wrapped round";
        }
    }
}
