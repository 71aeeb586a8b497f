// Radial blur (Shader effects §3.6, hard cases 1 to 4): the identities the chapter promises and the
// 0/0 at the centre pixel, read back as floats.
#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>

#include "effects/post/radial_blur.hpp"
#include "gl_test.hpp"
#include "image/image_stats.hpp"
#include "test_fullscreen_harness.hpp"

using namespace fx;
using fx::test::EffectRunner;
using fx::test::hashedValue;
using fx::test::makeImage;

namespace {

// Arbitrary float values (HDR, negative, tiny) from an integer hash: nothing a blur could smooth away.
FloatImage patterned(int width, int height) {
    return makeImage(width, height, [](int x, int y) {
        std::array<float, 4> v{};
        for (int c = 0; c < 4; ++c)
            v[std::size_t(c)] = (hashedValue(x, y, c) - 0.25f) * (c == 0 ? 3000.0f : 1.5f);
        return v;
    });
}

bool sameBits(float a, float b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

bool finite(const FloatImage& image, int x, int y) {
    for (int c = 0; c < image.channels; ++c) {
        if (!std::isfinite(image.texel(x, y, c))) return false;
    }
    return true;
}

// Runs the blur (or its offsets, `offsets` true) on `input` stored as `format`.
FloatImage blur(EffectRunner& runner, const RadialBlur& effect, const FloatImage& input,
                const RadialBlurParams& params, TextureFormat format, bool offsets = false) {
    return runner.run(input, format, [&](FrameGraph& g, TextureHandle in) {
        RadialBlur::Declared d = effect.declare(g, in, params, format);
        return offsets ? d.offsets.output : d.blur.output;
    });
}

class RadialBlurOnGl : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        ASSERT_TRUE(programsBuilt());
    }
    RadialBlur effect;
};

}  // namespace

TEST_F(RadialBlurOnGl, LengthZeroIsTheIdentityBitForBit) {
    for (TextureFormat format : {TextureFormat::RGBA32F, TextureFormat::RGBA16F}) {
        EffectRunner runner(37, 23);
        for (RadialBlurFormula formula :
             {RadialBlurFormula::firstVersion, RadialBlurFormula::chapter, RadialBlurFormula::guarded}) {
            RadialBlurParams params;
            params.length = 0.0f;
            params.formula = formula;
            params.samples = 64;
            FloatImage out = blur(runner, effect, patterned(37, 23), params, format);
            ASSERT_FALSE(out.empty()) << runner.lastError;
            std::size_t differing = 0;
            for (std::size_t i = 0; i < out.texels.size(); ++i)
                differing += !sameBits(out.texels[i], runner.storedInput.texels[i]);
            EXPECT_EQ(differing, 0u) << toString(format) << ", " << describe(formula).name;
        }
    }
}

TEST_F(RadialBlurOnGl, UniformImageIsUnchangedForEverySampleCount) {
    // The weights are 1/samples and add up to 1 for every count, so the blur neither brightens nor darkens.
    FloatImage grey = makeImage(40, 24, [](int, int) {
        return std::array<float, 4>{0.3f, 7.5f, 0.0625f, 1.0f};
    });
    for (TextureFormat format : {TextureFormat::RGBA16F, TextureFormat::RGBA32F}) {
        EffectRunner runner(40, 24);
        for (int samples : {1, 2, 3, 4, 5, 7, 8, 13, 16, 32, 33, 64, 100, 256}) {
            RadialBlurParams params;
            params.samples = samples;
            params.length = 0.05f;
            params.start = 0.1f;
            FloatImage out = blur(runner, effect, grey, params, format);
            ASSERT_FALSE(out.empty()) << runner.lastError;
            float worst = 0;
            for (std::size_t i = 0; i < out.texels.size(); ++i) {
                float expected = runner.storedInput.texels[i];
                worst = std::max(worst, std::abs(out.texels[i] - expected) / expected);
            }
            // The weights are exact, but bilinear filtering of two equal float texels may round in the
            // last bit (llvmpipe's does). That is far below a half float's precision, so the lesson's
            // RGBA16F pictures come back exactly; a float32 target is within a few units in the last place.
            EXPECT_LE(worst, format == TextureFormat::RGBA16F ? 0.0f : 2e-6f)
                << toString(format) << ", " << samples;
        }
    }
}

TEST_F(RadialBlurOnGl, PixelsInsideTheStartRadiusAreUnchangedExactly) {
    EffectRunner runner(48, 48);
    RadialBlurParams params;
    params.start = 0.2f;
    params.length = 0.08f;
    FloatImage out = blur(runner, effect, patterned(48, 48), params, TextureFormat::RGBA32F);
    ASSERT_FALSE(out.empty()) << runner.lastError;
    int inside = 0, changedOutside = 0;
    for (int y = 0; y < 48; ++y) {
        for (int x = 0; x < 48; ++x) {
            glm::vec2 d = (glm::vec2(24.0f) - glm::vec2(x + 0.5f, y + 0.5f)) / 48.0f;
            bool within = glm::length(d) < 0.199f;
            bool same = true;
            for (int c = 0; c < 4; ++c)
                same = same && sameBits(out.texel(x, y, c), runner.storedInput.texel(x, y, c));
            if (within) {
                ++inside;
                EXPECT_TRUE(same) << "pixel " << x << ", " << y << " inside the start radius changed";
            } else if (glm::length(d) > 0.3f && !same) {
                ++changedOutside;
            }
        }
    }
    EXPECT_GT(inside, 100);
    EXPECT_GT(changedOutside, 100) << "outside the start radius the blur must do something";
}

TEST_F(RadialBlurOnGl, LinearRampGainsThreeAndAHalfTapOffsets) {
    // The chapter's test vector: on a ramp rising toward the centre with slope s, the average of the
    // taps is f + 3.5 s z (|d| - w)+, whatever the sample count (the taps spread over the same streak).
    const int width = 64, height = 9;
    FloatImage ramp = makeImage(width, height, [&](int x, int) {
        float u = (float(x) + 0.5f) / float(width);
        return std::array<float, 4>{u, u, u, 1.0f};
    });
    EffectRunner runner(width, height);
    for (int samples : {2, 4, 8, 16, 64, 256}) {
        RadialBlurParams params;
        params.centre = {0.75f, (4.5f) / float(height)};  // on the middle row: d is horizontal there
        params.length = 0.02f;
        params.start = 0.1f;
        params.samples = samples;
        FloatImage out = blur(runner, effect, ramp, params, TextureFormat::RGBA32F);
        ASSERT_FALSE(out.empty()) << runner.lastError;
        for (int x : {2, 10, 20, 30}) {
            float u = (float(x) + 0.5f) / float(width);
            float distance = 0.75f - u;
            float expected = u + 3.5f * 1.0f * params.length * std::max(distance - params.start, 0.0f);
            // Bilinear weights have a few bits of sub-texel precision: 1/256 of a texel step of the ramp.
            EXPECT_NEAR(out.texel(x, 4, 0), expected, 1.0f / float(width) / 256.0f + 1e-6f)
                << samples << " samples, pixel " << x;
        }
    }
}

TEST_F(RadialBlurOnGl, CentrePixelIsFiniteGuardedAndNaNWithTheChaptersFormula) {
    // 33x17: the default centre (0.5, 0.5) is the centre of pixel (16, 8), as in any odd-sized window.
    EffectRunner runner(33, 17);
    FloatImage input = patterned(33, 17);
    RadialBlurParams params;  // the chapter's defaults
    ASSERT_EQ(radialBlurCentrePixels(params, {33, 17}), glm::vec2(16.5f, 8.5f));

    params.formula = RadialBlurFormula::guarded;
    FloatImage offsets = blur(runner, effect, input, params, TextureFormat::RGBA16F, true);
    FloatImage result = blur(runner, effect, input, params, TextureFormat::RGBA16F);
    ASSERT_FALSE(offsets.empty() || result.empty()) << runner.lastError;
    EXPECT_EQ(offsets.texel(16, 8, 0), 0.0f);
    EXPECT_EQ(offsets.texel(16, 8, 1), 0.0f);
    for (const ChannelStats& s : computeStats(result)) EXPECT_EQ(s.nanCount + s.infCount, 0);
    for (const ChannelStats& s : computeStats(offsets)) EXPECT_EQ(s.nanCount + s.infCount, 0);
    for (int c = 0; c < 4; ++c)
        EXPECT_TRUE(sameBits(result.texel(16, 8, c), runner.storedInput.texel(16, 8, c)));

    params.formula = RadialBlurFormula::chapter;
    offsets = blur(runner, effect, input, params, TextureFormat::RGBA16F, true);
    ASSERT_FALSE(offsets.empty()) << runner.lastError;
    EXPECT_TRUE(std::isnan(offsets.texel(16, 8, 0)) && std::isnan(offsets.texel(16, 8, 1)))
        << "the chapter's formula divides 0 by 0 at the centre pixel; got " << offsets.texel(16, 8, 0);
    // Only there: every other pixel has a direction.
    std::int64_t nan = 0;
    for (const ChannelStats& s : computeStats(offsets)) nan += s.nanCount;
    EXPECT_EQ(nan, 2);
    // The CPU reference agrees.
    EXPECT_TRUE(std::isnan(radialBlurTapOffset(params, {33, 17}, {16.5f, 8.5f}).x));
}

TEST_F(RadialBlurOnGl, TheChaptersFormulaIsTheOnlyDeliberateBug) {
    EXPECT_TRUE(describe(RadialBlurFormula::chapter).deliberateBug);
    EXPECT_FALSE(describe(RadialBlurFormula::guarded).deliberateBug);
    EXPECT_FALSE(describe(RadialBlurFormula::firstVersion).deliberateBug);
    EXPECT_EQ(RadialBlurParams{}.formula, RadialBlurFormula::guarded)
        << "the default must be the fixed formula";
}

TEST_F(RadialBlurOnGl, CentreOffScreenGivesFiniteOutput) {
    EffectRunner runner(40, 30);
    RadialBlurParams params;
    params.centre = {-3.0f, 2.0f};
    params.length = 0.1f;
    params.start = 0.0f;
    params.samples = 32;
    FloatImage input = makeImage(40, 30, [](int x, int y) {
        return std::array<float, 4>{hashedValue(x, y, 0) * 4.0f, hashedValue(x, y, 1), hashedValue(x, y, 2),
                                    1.0f};
    });
    for (RadialBlurFormula formula :
         {RadialBlurFormula::guarded, RadialBlurFormula::chapter, RadialBlurFormula::firstVersion}) {
        params.formula = formula;
        FloatImage out = blur(runner, effect, input, params, TextureFormat::RGBA16F);
        FloatImage offsets = blur(runner, effect, input, params, TextureFormat::RGBA16F, true);
        ASSERT_FALSE(out.empty() || offsets.empty()) << runner.lastError;
        for (int y = 0; y < 30; ++y) {
            for (int x = 0; x < 40; ++x)
                ASSERT_TRUE(finite(out, x, y) && finite(offsets, x, y)) << x << ", " << y;
        }
        // Taps that leave the screen read its edge: the average stays inside the input's range.
        for (const ChannelStats& s : computeStats(out)) EXPECT_GE(s.min, 0.0f);
    }
}

TEST_F(RadialBlurOnGl, GpuOffsetsMatchTheCpuReference) {
    EffectRunner runner(50, 20);
    RadialBlurParams params;
    params.centre = {0.3f, 0.8f};
    params.length = 0.05f;
    params.start = 0.15f;
    for (RadialBlurFormula formula : {RadialBlurFormula::guarded, RadialBlurFormula::firstVersion}) {
        params.formula = formula;
        FloatImage offsets = blur(runner, effect, patterned(50, 20), params, TextureFormat::RGBA16F, true);
        ASSERT_FALSE(offsets.empty()) << runner.lastError;
        for (int y = 0; y < 20; ++y) {
            for (int x = 0; x < 50; ++x) {
                glm::vec2 v = radialBlurTapOffset(params, {50, 20}, {x + 0.5f, y + 0.5f});
                for (int c = 0; c < 2; ++c) {
                    EXPECT_NEAR(offsets.texel(x, y, c), v[c], std::abs(v[c]) / 1024.0f + 1e-7f)
                        << x << ", " << y;
                }
            }
        }
    }
}

namespace {

// A bright column at the left edge, and a centre off screen to the right that sends the right edge's
// taps past it (up to 7 x 0.1 x 0.25 of the width). With CLAMP_TO_EDGE they read the dark right edge;
// REPEAT would bring in the bright column (Shader effects: "REPEAT pulls in the opposite edge").
constexpr int kEdgeW = 64, kEdgeH = 16;
FloatImage brightLeftColumn() {
    return makeImage(kEdgeW, kEdgeH, [](int x, int) {
        float v = x < 8 ? 50.0f : 0.25f;
        return std::array<float, 4>{v, v, v, 1.0f};
    });
}
RadialBlurParams pastTheRightEdge() {
    RadialBlurParams params;
    params.centre = {1.25f, 0.5f};
    params.length = 0.1f;
    params.start = 0.0f;
    return params;
}
void expectRightEdgeDark(const FloatImage& out) {
    for (int y = 0; y < kEdgeH; ++y) {
        for (int x = kEdgeW - 4; x < kEdgeW; ++x)
            EXPECT_NEAR(out.texel(x, y, 0), 0.25f, 1e-5f)
                << "pixel " << x << ", " << y << ": light wrapped round";
    }
}

}  // namespace

TEST_F(RadialBlurOnGl, TapsPastTheRightEdgeDoNotFetchTheLeftEdge) {
    EffectRunner runner(kEdgeW, kEdgeH);
    FloatImage out = blur(runner, effect, brightLeftColumn(), pastTheRightEdge(), TextureFormat::RGBA32F);
    ASSERT_FALSE(out.empty()) << runner.lastError;
    expectRightEdgeDark(out);
}

TEST_F(RadialBlurOnGl, TheBlurSamplesWithItsOwnSamplerNotTheTexturesParameters) {
    // The input texture itself says REPEAT and NEAREST (as a texture made for tiling would): the blur
    // binds its own sampler, so its taps still clamp to the edge and filter bilinearly.
    EffectRunner runner(kEdgeW, kEdgeH);
    FloatImage out =
        runner.run(brightLeftColumn(), TextureFormat::RGBA32F, [&](FrameGraph& g, TextureHandle in) {
            GLuint texture = GLuint(g.texture(in).native);
            EXPECT_NE(texture, 0u);
            glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_REPEAT);
            glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_REPEAT);
            glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            return effect.declare(g, in, pastTheRightEdge(), TextureFormat::RGBA32F).blur.output;
        });
    ASSERT_FALSE(out.empty()) << runner.lastError;
    expectRightEdgeDark(out);
}

TEST_F(RadialBlurOnGl, NegativeLengthIsNoBlurAndNoOffset) {
    // Shader effects, hard case 3: z <= 0 skips the blur. The effect clamps a negative length to 0
    // itself (a scene file or a script need not go through the slider), so the offsets it shows are 0
    // too, not taps pointing away from the centre.
    EffectRunner runner(40, 30);
    RadialBlurParams params;
    params.start = 0.0f;
    for (float length : {-0.05f, -INFINITY, NAN}) {
        params.length = length;
        FloatImage out = blur(runner, effect, patterned(40, 30), params, TextureFormat::RGBA32F);
        FloatImage offsets = blur(runner, effect, patterned(40, 30), params, TextureFormat::RGBA32F, true);
        ASSERT_FALSE(out.empty() || offsets.empty()) << runner.lastError;
        std::size_t differing = 0, moved = 0;
        for (std::size_t i = 0; i < out.texels.size(); ++i)
            differing += !sameBits(out.texels[i], runner.storedInput.texels[i]);
        for (float v : offsets.texels) moved += v != 0.0f;
        EXPECT_EQ(differing, 0u) << "length " << length;
        EXPECT_EQ(moved, 0u) << "length " << length << ": offsets drawn for a blur that does not run";
        EXPECT_EQ(radialBlurTapOffset(params, {40, 30}, {3.5f, 3.5f}), glm::vec2(0.0f));
    }
}

TEST_F(RadialBlurOnGl, NegativeStartIsStartZero) {
    // Hard case 2: w < 0 makes |d| - w larger than |d|, more blur than any w >= 0 gives, and with the
    // chapter's formula +x/0 at the centre pixel. The effect clamps it to 0: the same picture bit for bit.
    EffectRunner runner(33, 17);
    RadialBlurParams zero;
    zero.start = 0.0f;
    zero.length = 0.05f;
    FloatImage expected = blur(runner, effect, patterned(33, 17), zero, TextureFormat::RGBA32F);
    ASSERT_FALSE(expected.empty()) << runner.lastError;
    for (float start : {-0.3f, NAN}) {
        RadialBlurParams negative = zero;
        negative.start = start;
        FloatImage out = blur(runner, effect, patterned(33, 17), negative, TextureFormat::RGBA32F);
        ASSERT_FALSE(out.empty()) << runner.lastError;
        std::size_t differing = 0;
        for (std::size_t i = 0; i < out.texels.size(); ++i)
            differing += !sameBits(out.texels[i], expected.texels[i]);
        EXPECT_EQ(differing, 0u) << "start " << start;
    }
}

TEST_F(RadialBlurOnGl, LengthAboveOneSeventhOvershootsTheCentre) {
    // Hard case 3: the farthest of the 8 taps sits 7 z |d| toward the centre (start 0), so it passes
    // the centre once z > 1/7. Black left of the centre, 1 right of it, a pixel 0.4 of the width to the
    // left: at z = 0.13 the farthest tap stops 0.036 short (all 8 read black); at z = 0.16 it lands
    // 0.048 beyond (one tap of 8 reads the right half: 1/8) and the seventh, at 0.384, still falls short.
    const int w = 128, h = 65;  // an odd height: the middle row's pixel centres lie on the centre's y
    EffectRunner runner(w, h);
    FloatImage input = makeImage(w, h, [](int x, int) {
        float v = x < w / 2 ? 0.0f : 1.0f;
        return std::array<float, 4>{v, v, v, 1.0f};
    });
    const int x = int(0.1f * w), y = h / 2;  // its centre is 0.4 of the width from the blur centre's
    RadialBlurParams params;
    params.start = 0.0f;
    params.length = 0.13f;
    FloatImage shortOf = blur(runner, effect, input, params, TextureFormat::RGBA32F);
    params.length = 0.16f;
    FloatImage past = blur(runner, effect, input, params, TextureFormat::RGBA32F);
    ASSERT_FALSE(shortOf.empty() || past.empty()) << runner.lastError;
    EXPECT_EQ(shortOf.texel(x, y, 0), 0.0f);
    EXPECT_NEAR(past.texel(x, y, 0), 1.0f / 8.0f, 1e-6f) << "the farthest tap crossed to the other side";
}

TEST_F(RadialBlurOnGl, StartBeyondTheCornerDistanceBlursNothing) {
    // Exercise 03's second answer: a centred blur's farthest pixel is about 0.7071 away (corner), so a
    // start of 0.7072 leaves every pixel as it was; at 0.68 the corners blur.
    EffectRunner runner(64, 48);
    RadialBlurParams params;
    params.length = 0.1f;
    for (float start : {0.7072f, 0.68f}) {
        params.start = start;
        FloatImage out = blur(runner, effect, patterned(64, 48), params, TextureFormat::RGBA32F);
        ASSERT_FALSE(out.empty()) << runner.lastError;
        std::size_t differing = 0;
        for (std::size_t i = 0; i < out.texels.size(); ++i)
            differing += !sameBits(out.texels[i], runner.storedInput.texels[i]);
        if (start > 0.7071f) {
            EXPECT_EQ(differing, 0u) << "start " << start;
        } else {
            EXPECT_GT(differing, 0u) << "start " << start << ": the corners are farther than that";
        }
    }
}

TEST_F(RadialBlurOnGl, StartRadiusIsAnEllipseOnANonSquareTarget) {
    // The start radius is measured in texture coordinates, so on a 4:1 target start 0.25 keeps 32
    // pixels sharp horizontally and 8 vertically. Every pixel within 0.245 (texture units) is unchanged
    // bit for bit, every one beyond 0.26 is blurred: 30 pixels to the right stays sharp, 9 below does not.
    const int w = 128, h = 32;
    EffectRunner runner(w, h);
    RadialBlurParams params;
    params.start = 0.25f;
    params.length = 0.1f;
    FloatImage out = blur(runner, effect, patterned(w, h), params, TextureFormat::RGBA32F);
    ASSERT_FALSE(out.empty()) << runner.lastError;
    auto unchanged = [&](int x, int y) {
        bool same = true;
        for (int c = 0; c < 4; ++c)
            same = same && sameBits(out.texel(x, y, c), runner.storedInput.texel(x, y, c));
        return same;
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            glm::vec2 d((0.5f * w - (x + 0.5f)) / w, (0.5f * h - (y + 0.5f)) / h);
            float distance = glm::length(d);
            if (distance < 0.245f) {
                EXPECT_TRUE(unchanged(x, y)) << x << ", " << y << " is inside the ellipse";
            } else if (distance > 0.26f) {
                EXPECT_FALSE(unchanged(x, y)) << x << ", " << y << " is outside the ellipse";
            }
        }
    EXPECT_TRUE(unchanged(64 + 30, 15));
    EXPECT_FALSE(unchanged(63, 15 - 9));
}

TEST_F(RadialBlurOnGl, ChaptersFormulaHasNoNanOnAnEvenSizedTarget) {
    // Hard case 1: with the centre (0.5, 0.5) on an even-sized target the centre is a pixel corner, so
    // no pixel has d = 0 and the chapter's unguarded formula stays finite everywhere.
    EffectRunner runner(64, 32);
    RadialBlurParams params;  // the chapter's defaults
    params.formula = RadialBlurFormula::chapter;
    FloatImage out = blur(runner, effect, patterned(64, 32), params, TextureFormat::RGBA16F);
    FloatImage offsets = blur(runner, effect, patterned(64, 32), params, TextureFormat::RGBA16F, true);
    ASSERT_FALSE(out.empty() || offsets.empty()) << runner.lastError;
    for (const ChannelStats& s : computeStats(out)) EXPECT_EQ(s.nanCount + s.infCount, 0);
    for (const ChannelStats& s : computeStats(offsets)) EXPECT_EQ(s.nanCount + s.infCount, 0);
    EXPECT_EQ(radialBlurCentrePixels(params, {64, 32}), glm::vec2(32.0f, 16.0f)) << "a pixel corner";
}
