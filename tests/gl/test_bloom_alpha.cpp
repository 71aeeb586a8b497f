// Bloom (lesson 06): what the alpha channel of every bloom texture holds. The Bloom chapter blends
// additively with alpha included, so its level alphas grow past 1 (hard case 15) and break any later
// pass that blends with the scene's alpha. Here every pass writes alpha 1 itself, whatever the scene's
// alpha; the reference's one-direction blurs write 0, added onto a sum whose clear sets 1.
#include "effects/bloom/bloom_flicker.hpp"
#include "gl_test.hpp"
#include "test_bloom_harness.hpp"

using namespace fx;
using namespace fx::test;

namespace {

class BloomAlpha : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        ASSERT_TRUE(programsBuilt());
    }
    BloomEffects effects;
};

// A bright orange scene whose alpha is 0.3 everywhere: nothing in bloom may pass it on or add it up.
FloatImage translucentOrange(int width, int height) {
    return makeImage(width, height, [](int, int) { return std::array<float, 4>{3.0f, 1.0f, 0.5f, 0.3f}; });
}

// Every texel's alpha is `expected` exactly.
::testing::AssertionResult everyAlphaIs(const FloatImage& image, float expected) {
    if (image.empty()) return ::testing::AssertionFailure() << "nothing was read back";
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (image.texel(x, y, 3) != expected)
                return ::testing::AssertionFailure() << "alpha at (" << x << ", " << y << ") is "
                                                     << image.texel(x, y, 3) << ", expected " << expected;
    return ::testing::AssertionSuccess();
}

}  // namespace

TEST_F(BloomAlpha, EveryLevelAndTheResultHoldAlphaOne) {
    const int w = 128, h = 64;
    EffectRunner runner(w, h);
    FloatImage scene = translucentOrange(w, h);
    BloomChainSettings beyond = beyondChapters(6);
    beyond.knee = 0.5f;
    const std::pair<const char*, BloomChainSettings> chains[] = {
        {"Shader effects", shaderEffectsChain(1.0f, 2.0f, 6)},
        {"Bloom chapter", bloomChapterChain(1.0f, 6)},
        {"beyond", beyond}};
    for (const auto& [name, settings] : chains) {
        int levels = 0;
        FloatImage result =
            runBloom(runner, effects, scene, TextureFormat::RGBA16F, settings, 2.0f, "result", &levels);
        EXPECT_TRUE(everyAlphaIs(result, 1.0f)) << name << ": bloom.result " << runner.lastError;
        ASSERT_GT(levels, 1) << name;
        for (int k = 0; k < levels; ++k) {
            FloatImage down = runChain(runner, effects, scene, TextureFormat::RGBA16F, settings,
                                       [k](const BloomChain::Declared& d) { return d.down[std::size_t(k)]; });
            EXPECT_TRUE(everyAlphaIs(down, 1.0f)) << name << ": bloom.down[" << k << "]";
            if (k + 1 == levels) continue;  // the smallest level has no accumulated copy
            FloatImage up = runChain(runner, effects, scene, TextureFormat::RGBA16F, settings,
                                     [k](const BloomChain::Declared& d) { return d.up[std::size_t(k)]; });
            EXPECT_TRUE(everyAlphaIs(up, 1.0f)) << name << ": bloom.up[" << k << "]";
        }
    }
}

TEST_F(BloomAlpha, ReferenceBlursWriteZeroAndItsSumHoldsOne) {
    // The reference adds its levels with blending (ONE, ONE): a Gaussian that wrote alpha 1 would leave
    // the sum's alpha at 1 + the number of levels.
    const int w = 64, h = 32;
    EffectRunner runner(w, h);
    FloatImage scene = translucentOrange(w, h);
    BloomReferenceSettings settings{1.0f, 0.0f, {1.0, 2.0, 4.0}, 1.0f / 3.0f};
    using Pick = TextureHandle (*)(FrameGraph&, const BloomReference::Declared&);
    const std::pair<const char*, Pick> targets[] = {
        {"bloom.reference.bright", [](FrameGraph&, const BloomReference::Declared& d) { return d.bright; }},
        {"bloom.reference.blur_x[0]",
         [](FrameGraph& g, const BloomReference::Declared&) {
             return g.findTexture("bloom.reference.blur_x[0]").value();
         }},
        {"bloom.reference", [](FrameGraph&, const BloomReference::Declared& d) { return d.glow; }},
    };
    const float expected[] = {1.0f, 0.0f, 1.0f};
    for (std::size_t i = 0; i < 3; ++i) {
        FloatImage out = runner.run(scene, TextureFormat::RGBA32F, [&](FrameGraph& g, TextureHandle in) {
            return targets[i].second(g, effects.reference.declare(g, in, settings));
        });
        EXPECT_TRUE(everyAlphaIs(out, expected[i])) << targets[i].first << " " << runner.lastError;
    }
}

TEST_F(BloomAlpha, FlickerMapHoldsAlphaOne) {
    const int w = 64, h = 32;
    EffectRunner runner(w, h);
    BloomFlicker flicker;
    ASSERT_TRUE(programsBuilt());
    FloatImage out =
        runner.run(translucentOrange(w, h), TextureFormat::RGBA16F, [&](FrameGraph& g, TextureHandle in) {
            BloomChain::Declared d = effects.chain.declare(g, in, bloomChapterChain(1.0f, 3));
            return flicker.declare(g, d.glow(), d.levels[0].size, true).output;
        });
    EXPECT_TRUE(everyAlphaIs(out, 1.0f)) << "bloom.flicker " << runner.lastError;
}
