// The pixel probe reads the exact stored value of a texel from the texture itself, in any level
// and in every member of a chain; the view, the range and the channel toggles change nothing in it.
#include <cmath>
#include <cstring>
#include <limits>

#include "gl/texture.hpp"
#include "gl_test.hpp"
#include "ui/pixel_probe.hpp"

using namespace fx;

namespace {

bool sameBits(float a, float b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

}  // namespace

class UiProbe : public GlTest {};

TEST_F(UiProbe, ReturnsTheExactFloatWrittenAtATexel) {
    auto t = gl::Texture::create2D(TextureFormat::RGBA32F, 7, 5, 3, "test.probe");
    std::vector<float> zeros(7 * 5 * 4, 0.25f);
    glTextureSubImage2D(t.name(), 0, 0, 0, 7, 5, GL_RGBA, GL_FLOAT, zeros.data());
    const float inf = std::numeric_limits<float>::infinity();
    const float planted[4] = {0.1f, -1234.5678f, 1e-40f /* denormal */, inf};
    glTextureSubImage2D(t.name(), 0, 5, 3, 1, 1, GL_RGBA, GL_FLOAT, planted);

    ProbeSample s = probeTexel(textureSource(t), 0, 5, 3);
    ASSERT_EQ(s.channels, 4);
    for (int c = 0; c < 4; ++c) EXPECT_TRUE(sameBits(s.texel.value[c], planted[c])) << "channel " << c;
    EXPECT_EQ(exactFloatText(s.texel.value[0]), "0.1");
    EXPECT_EQ(exactFloatText(s.texel.value[1]), "-1234.5677");
    EXPECT_EQ(exactFloatText(s.texel.value[3]), "inf");
    // Its neighbour is untouched.
    EXPECT_EQ(probeTexel(textureSource(t), 0, 4, 3).texel.value[0], 0.25f);
}

TEST_F(UiProbe, ReadsNanAndOtherLevels) {
    auto t = gl::Texture::create2D(TextureFormat::RGBA16F, 9, 9, 4, "test.probe levels");
    const float level2[4] = {std::nanf(""), 2.5f, -0.5f, 1.0f};
    glTextureSubImage2D(t.name(), 2, 1, 0, 1, 1, GL_RGBA, GL_FLOAT, level2);
    ProbeSample s = probeTexel(textureSource(t), 2, 1, 0);
    ASSERT_EQ(s.channels, 4);
    EXPECT_EQ(s.size, (Size2D{2, 2}));
    EXPECT_TRUE(std::isnan(s.texel.value[0]));
    EXPECT_EQ(s.texel.value[1], 2.5f);
    EXPECT_EQ(s.texel.value[2], -0.5f);
}

TEST_F(UiProbe, ReadsDepthAsStored) {
    auto t = gl::Texture::create2D(TextureFormat::Depth32F, 4, 4, 1, "test.probe depth");
    std::vector<float> depth(16, 1.0f);
    depth[2 * 4 + 3] = 0.987654321f;
    glTextureSubImage2D(t.name(), 0, 0, 0, 4, 4, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    ProbeSample s = probeTexel(textureSource(t), 0, 3, 2);
    ASSERT_EQ(s.channels, 1);
    EXPECT_EQ(s.texel.value[0], 0.987654321f);
}

TEST_F(UiProbe, OutsideTheLevelReadsNothing) {
    auto t = gl::Texture::create2D(TextureFormat::RGBA8, 4, 4, 1, "test.probe outside");
    EXPECT_EQ(probeTexel(textureSource(t), 0, 4, 0).channels, 0);
    EXPECT_EQ(probeTexel(textureSource(t), 0, -1, 0).channels, 0);
    EXPECT_EQ(probeTexel(textureSource(t), 1, 0, 0).channels, 0);
    EXPECT_EQ(probeTexel(TextureSource{}, 0, 0, 0).channels, 0);
}

TEST_F(UiProbe, FindsTheSameTexelInEveryLevelOfAChain) {
    auto t = gl::Texture::create2D(TextureFormat::R32F, 1279, 719, 11, "test.probe chain");
    // Each level holds its own number, so the value read says which level it came from.
    for (int level = 0; level < 11; ++level) {
        int w = mipLevelSize(1279, level), h = mipLevelSize(719, level);
        std::vector<float> fill(std::size_t(w) * h, float(level) + 0.5f);
        glTextureSubImage2D(t.name(), level, 0, 0, w, h, GL_RED, GL_FLOAT, fill.data());
    }
    TextureChain chain = mipChain("test.probe chain", {1279, 719, TextureFormat::R32F, 11});
    auto samples =
        probeChain(chain, [&](const std::string&) { return textureSource(t); }, 1000, 700, {1279, 719});
    ASSERT_EQ(samples.size(), 11u);
    for (int level = 0; level < 11; ++level) {
        const ProbeSample& s = samples[std::size_t(level)];
        EXPECT_EQ(s.texel.value[0], float(level) + 0.5f) << level;
        EXPECT_LT(s.x, s.size.width);
        EXPECT_LT(s.y, s.size.height);
    }
    // The last level is 1x1: everything maps to its one texel.
    EXPECT_EQ(samples.back().x, 0);
    EXPECT_EQ(samples.back().y, 0);
    // Level 1 of 1279 is 639 wide: texel 1000 covers [1000, 1001)/1279 of the width -> 499.
    EXPECT_EQ(samples[1].x, 499);
}

TEST(UiProbeText, ShortestExactFloats) {
    EXPECT_EQ(exactFloatText(0.5f), "0.5");
    EXPECT_EQ(exactFloatText(65504.0f), "65504");
    EXPECT_EQ(exactFloatText(1.0f / 3.0f), "0.33333334");
    EXPECT_EQ(exactFloatText(-std::numeric_limits<float>::infinity()), "-inf");
    EXPECT_EQ(exactFloatText(std::nanf("")), "nan");
    EXPECT_EQ(storedValueText(128.0f / 255.0f, TextureFormat::RGBA8), "0.5019608 (128/255)");
}
