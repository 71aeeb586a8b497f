// Colour matrix (Shader effects §3.5, hard cases 5 to 7): the CPU maths of ColourTransform, and the
// GPU pass against it on known colours, read back as floats.
#include <cmath>
#include <limits>

#include "effects/post/colour_matrix.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "gl_test.hpp"
#include "image/image_stats.hpp"
#include "test_fullscreen_harness.hpp"

using namespace fx;
using fx::test::EffectRunner;
using fx::test::makeImage;

namespace {

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance,
                const std::string& what) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], expected[c], tolerance) << what << ", channel " << c;
}

// The colours every preset is checked on: primaries, white, black, greys, a dull colour, an HDR one.
const std::vector<glm::vec3> kColours{
    {1, 0, 0},
    {0, 1, 0},
    {0, 0, 1},
    {1, 1, 1},
    {0, 0, 0},
    {0.18f, 0.18f, 0.18f},
    {0.5f, 0.25f, 0.125f},
    {0.9f, 0.04f, 0.04f},
    {3.0f, 1.5f, 0.25f},
    {0.05f, 0.8f, 0.08f},
    {12.0f, 0.0f, 40.0f},
};

struct Named {
    const char* name;
    ColourTransform transform;
};

std::vector<Named> presets() {
    return {
        {"identity", ColourTransform::identity()},
        {"grayscale", ColourTransform::grayscale()},
        {"sepia", ColourTransform::sepia()},
        {"saturation 1.8", ColourTransform::saturation(1.8f)},
        {"saturation 0", ColourTransform::saturation(0.0f)},
        {"hue rotation 120", ColourTransform::hueRotation(120.0f)},
        {"hue rotation -35", ColourTransform::hueRotation(-35.0f)},
        {"channel swap gbr", ColourTransform::channelSwap({1, 2, 0})},
        {"brightness 0.1, contrast 1.4", ColourTransform::brightnessContrast(0.1f, 1.4f)},
        {"invert", ColourTransform::invert()},
        {"-I", ColourTransform::negate()},
        {"sepia at amount 0.5", blendFromIdentity(ColourTransform::sepia(), 0.5f)},
        {"invert then grayscale", then(ColourTransform::invert(), ColourTransform::grayscale())},
    };
}

// One texel per colour, in a row.
FloatImage colourRow() {
    return makeImage(int(kColours.size()), 1, [](int x, int) {
        glm::vec3 c = kColours[std::size_t(x)];
        return std::array<float, 4>{c.r, c.g, c.b, 1.0f};
    });
}

glm::vec3 texelRgb(const FloatImage& image, int x, int y) {
    return {image.texel(x, y, 0), image.texel(x, y, 1), image.texel(x, y, 2)};
}

// What the pass must write: the CPU transform of the stored input, clamped like the shader.
glm::vec3 reference(const ColourTransform& t, const glm::vec3& stored) {
    return glm::clamp(t.apply(stored), glm::vec3(0.0f), glm::vec3(kSceneHdrMax));
}

// Half floats keep 11 significant bits: the GPU computes in 32-bit floats and rounds once on the way
// into RGBA16F. GL leaves the rounding mode open (llvmpipe truncates), so a result is within one unit
// in the last place of the half (2^-10 relative), plus the float32 sum's own rounding.
float halfTolerance(float expected) {
    return std::max(std::abs(expected), 1.0f / 16384.0f) / 1024.0f + 1e-6f;
}

}  // namespace

// --- CPU: the transform maths the GPU is checked against ---

TEST(ColourTransform, GrayscaleOfRedIsItsLumaInEveryChannel) {
    // The chapter's check for a transposed matrix: (0.2126, 0.7152, 0.0722) would be wrong.
    expectNear(ColourTransform::grayscale().apply({1, 0, 0}), glm::vec3(0.2126f), 1e-7f, "grayscale of red");
    expectNear(ColourTransform::grayscale().apply({1, 1, 1}), glm::vec3(1.0f), 1e-6f, "grayscale of white");
    expectNear(ColourTransform::grayscale().row(0), {kLumaR, kLumaG, kLumaB}, 0.0f, "row red'");
}

TEST(ColourTransform, SepiaOfWhiteIsTheRowSums) {
    expectNear(ColourTransform::sepia().apply({1, 1, 1}), {1.175f, 0.948f, 0.670f}, 1e-6f, "sepia of white");
    expectNear(ColourTransform::sepia().row(0), {0.346f, 0.678f, 0.151f}, 0.0f, "sepia row red'");
}

TEST(ColourTransform, InvertMapsBlackToWhiteAndWhiteToBlack) {
    expectNear(ColourTransform::invert().apply({0, 0, 0}), glm::vec3(1.0f), 0.0f, "invert of black");
    expectNear(ColourTransform::invert().apply({1, 1, 1}), glm::vec3(0.0f), 0.0f, "invert of white");
    expectNear(ColourTransform::invert().apply({0.25f, 0.5f, 0.75f}), {0.75f, 0.5f, 0.25f}, 0.0f, "invert");
    EXPECT_FALSE(ColourTransform::invert().linear()) << "invert needs the offset";
}

TEST(ColourTransform, NoBareMatrixMapsBlackAnywhereButBlack) {
    // Why the lesson's transform is affine: M * 0 = 0 for every matrix, so -I (the best a 3x3 can do)
    // cannot give a negative; it makes every channel of every colour zero or negative.
    for (const Named& p : presets()) {
        if (p.transform.linear())
            expectNear(p.transform.apply(glm::vec3(0.0f)), glm::vec3(0.0f), 0.0f, p.name);
    }
    for (const glm::vec3& c : kColours) {
        glm::vec3 n = ColourTransform::negate().apply(c);
        EXPECT_LE(std::max({n.r, n.g, n.b}), 0.0f);
    }
}

TEST(ColourTransform, SaturationSpansGrayscaleToIdentity) {
    expectNear(ColourTransform::saturation(0.0f).apply({0.9f, 0.04f, 0.04f}),
               ColourTransform::grayscale().apply({0.9f, 0.04f, 0.04f}), 1e-6f, "saturation 0");
    expectNear(ColourTransform::saturation(1.0f).apply({0.9f, 0.04f, 0.04f}), {0.9f, 0.04f, 0.04f}, 1e-6f,
               "saturation 1");
    // Above 1, a saturated colour leaves [0, 1] on both sides: the hard case the clamp is for.
    glm::vec3 strong = ColourTransform::saturation(3.0f).apply({0.9f, 0.04f, 0.04f});
    EXPECT_GT(strong.r, 1.0f);
    EXPECT_LT(strong.g, 0.0f);
}

TEST(ColourTransform, HueRotationKeepsGreysAndComposesToFullTurns) {
    for (float degrees : {30.0f, 120.0f, -75.0f}) {
        expectNear(ColourTransform::hueRotation(degrees).apply(glm::vec3(0.4f)), glm::vec3(0.4f), 1e-6f,
                   "grey");
    }
    expectNear(ColourTransform::hueRotation(120.0f).apply({1, 0, 0}), {0, 1, 0}, 1e-6f,
               "red turned by 120 degrees");
    ColourTransform third = ColourTransform::hueRotation(120.0f);
    ColourTransform full = then(then(third, third), third);
    expectNear(full.apply({0.9f, 0.3f, 0.1f}), {0.9f, 0.3f, 0.1f}, 1e-5f, "three thirds of a turn");
}

TEST(ColourTransform, ChannelSwapPermutes) {
    expectNear(ColourTransform::channelSwap({1, 2, 0}).apply({0.1f, 0.2f, 0.3f}), {0.2f, 0.3f, 0.1f}, 0.0f,
               "gbr");
    expectNear(ColourTransform::channelSwap({2, 1, 0}).apply({0.1f, 0.2f, 0.3f}), {0.3f, 0.2f, 0.1f}, 0.0f,
               "bgr");
}

TEST(ColourTransform, BrightnessContrastPivotsOnMidGrey) {
    ColourTransform t = ColourTransform::brightnessContrast(0.0f, 2.0f);
    expectNear(t.apply(glm::vec3(kMidGrey)), glm::vec3(kMidGrey), 1e-7f, "mid grey stays");
    expectNear(t.apply(glm::vec3(0.28f)), glm::vec3(0.38f), 1e-6f, "0.1 above mid grey doubles");
    expectNear(ColourTransform::brightnessContrast(0.25f, 1.0f).apply(glm::vec3(0.0f)), glm::vec3(0.25f),
               1e-7f, "brightness is an offset");
}

TEST(ColourTransform, ThenAppliesInOrderAndBlendsAreExact) {
    ColourTransform a = ColourTransform::sepia(), b = ColourTransform::invert();
    glm::vec3 c(0.3f, 0.6f, 0.2f);
    expectNear(then(a, b).apply(c), b.apply(a.apply(c)), 1e-6f, "sepia then invert");
    expectNear(blendFromIdentity(b, 0.0f).apply(c), c, 0.0f, "amount 0");
    expectNear(blendFromIdentity(b, 1.0f).apply(c), b.apply(c), 1e-7f, "amount 1");
    expectNear(blendFromIdentity(b, 0.25f).apply(c), 0.75f * c + 0.25f * b.apply(c), 1e-6f, "amount 1/4");
}

// --- GPU: the pass against the CPU reference ---

class ColourMatrixOnGl : public GlTest {};

TEST_F(ColourMatrixOnGl, EveryPresetMatchesTheCpuWithinHalfFloatRounding) {
    ColourMatrixPass pass;
    ASSERT_TRUE(programsBuilt());
    EffectRunner runner(int(kColours.size()), 1);
    for (const Named& p : presets()) {
        pass.setTransform(p.transform);
        FloatImage out =
            runner.run(colourRow(), TextureFormat::RGBA16F,
                       [&](FrameGraph& g, TextureHandle in) { return pass.declare(g, in).output; });
        ASSERT_FALSE(out.empty()) << p.name << ": " << runner.lastError;
        for (int x = 0; x < out.width; ++x) {
            glm::vec3 expected = reference(p.transform, texelRgb(runner.storedInput, x, 0));
            glm::vec3 actual = texelRgb(out, x, 0);
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(actual[c], expected[c], halfTolerance(expected[c]))
                    << p.name << ", colour " << x << ", channel " << c;
            }
            EXPECT_EQ(out.texel(x, 0, 3), 1.0f) << "alpha passes through";
        }
    }
}

TEST_F(ColourMatrixOnGl, GrayscaleRedIsNotTransposedOnTheGpu) {
    ColourMatrixPass pass;
    pass.setTransform(ColourTransform::grayscale());
    OutputTransformPass present;  // the graph runs it later: keep it alive
    EffectRunner runner(1, 1);
    FloatImage red = makeImage(1, 1, [](int, int) { return std::array<float, 4>{1, 0, 0, 1}; });
    FloatImage out = runner.run(red, TextureFormat::RGBA16F, [&](FrameGraph& g, TextureHandle in) {
        DeclaredPass graded = pass.declare(g, in);
        present.declare(g, graded.output);
        return graded.output;
    });
    ASSERT_FALSE(out.empty()) << runner.lastError;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(out.texel(0, 0, c), 0.2126f, halfTolerance(0.2126f)) << c;
    // On screen: 0.2126 encodes to 0.4984 with the sRGB curve, 8-bit 127, in every channel (the
    // chapter's 1/2.2 power gives 126).
    for (int c = 0; c < 3; ++c) EXPECT_EQ(runner.presented.texel(0, 0, c), 127) << c;
}

TEST_F(ColourMatrixOnGl, InvertMapsZeroToOneAndOneToZero) {
    ColourMatrixPass pass;
    pass.setTransform(ColourTransform::invert());
    OutputTransformPass present;
    EffectRunner runner(2, 1);
    FloatImage input = makeImage(2, 1, [](int x, int) {
        float v = float(x);
        return std::array<float, 4>{v, v, v, 1};
    });
    FloatImage out = runner.run(input, TextureFormat::RGBA16F, [&](FrameGraph& g, TextureHandle in) {
        DeclaredPass graded = pass.declare(g, in);
        present.declare(g, graded.output);
        return graded.output;
    });
    ASSERT_FALSE(out.empty()) << runner.lastError;
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(out.texel(0, 0, c), 1.0f) << "black becomes white, channel " << c;
        EXPECT_EQ(out.texel(1, 0, c), 0.0f) << "white becomes black, channel " << c;
        EXPECT_EQ(runner.presented.texel(0, 0, c), 255);
        EXPECT_EQ(runner.presented.texel(1, 0, c), 0);
    }
}

TEST_F(ColourMatrixOnGl, NegativeOrLargeResultsNeverGiveNaN) {
    // Saturation 3, hue rotation, -I and a custom matrix with large and negative weights push channels
    // far below 0 and above 1; the chapter's pow(c, 1/2.2) would make the negative ones NaN.
    std::vector<ColourTransform> harsh{
        ColourTransform::saturation(3.0f), ColourTransform::hueRotation(150.0f), ColourTransform::negate(),
        ColourTransform::fromRows({4, -4, 2}, {-3, 0.5f, -3}, {0, 0, -4}, {-0.5f, 2, 0.25f})};
    // Every colour of the row, plus the brightest the scene writes.
    FloatImage input = makeImage(int(kColours.size()) + 1, 1, [](int x, int) {
        glm::vec3 c = x < int(kColours.size()) ? kColours[std::size_t(x)] : glm::vec3(kSceneHdrMax);
        return std::array<float, 4>{c.r, c.g, c.b, 1.0f};
    });
    ColourMatrixPass pass;
    OutputTransformPass present;
    EffectRunner runner(input.width, 1);
    int negativesBeforeClamp = 0;
    for (const ColourTransform& t : harsh) {
        pass.setTransform(t);
        FloatImage out = runner.run(input, TextureFormat::RGBA16F, [&](FrameGraph& g, TextureHandle in) {
            DeclaredPass graded = pass.declare(g, in);
            present.declare(g, graded.output);
            return graded.output;
        });
        ASSERT_FALSE(out.empty()) << runner.lastError;
        for (const ChannelStats& s : computeStats(out)) {
            EXPECT_EQ(s.nanCount, 0);
            EXPECT_EQ(s.infCount, 0);
            EXPECT_EQ(s.negativeCount, 0);
            EXPECT_LE(s.max, kSceneHdrMax);
        }
        for (int x = 0; x < input.width; ++x) {
            glm::vec3 raw = t.apply(texelRgb(runner.storedInput, x, 0));
            negativesBeforeClamp += (raw.r < 0) + (raw.g < 0) + (raw.b < 0);
            // Where the transform went negative the screen shows 0, not a NaN's arbitrary byte.
            for (int c = 0; c < 3; ++c) {
                if (raw[c] <= 0) {
                    EXPECT_EQ(runner.presented.texel(x, 0, c), 0) << "colour " << x << " channel " << c;
                }
                if (raw[c] >= 1) {
                    EXPECT_EQ(runner.presented.texel(x, 0, c), 255) << "colour " << x << " channel " << c;
                }
            }
        }
    }
    EXPECT_GT(negativesBeforeClamp, 20) << "the test must really produce negative channels";
}
