// NaN, infinite and negative texels: the inspector counts them from an exact read-back, and its
// view paints each kind in its own colour at exactly those texels.
#include <cmath>
#include <limits>

#include "gl/readback.hpp"
#include "gl/texture.hpp"
#include "gl_test.hpp"
#include "ui/texture_analysis.hpp"
#include "ui/texture_display.hpp"

using namespace fx;

namespace {

struct Planted {
    int x, y;
    float value[4];
};

const float kInf = std::numeric_limits<float>::infinity();

// 3 NaN texels (one with NaN and Inf together: it counts as NaN), 2 infinite, 4 negative.
const std::vector<Planted> kPlanted = {
    {1, 1, {std::nanf(""), 0, 0, 1}}, {7, 2, {0, std::nanf(""), 0, 1}}, {3, 9, {std::nanf(""), kInf, 0, 1}},
    {10, 4, {kInf, 0, 0, 1}},         {2, 6, {0, 0, -kInf, 1}},         {5, 5, {-0.5f, 0, 0, 1}},
    {6, 5, {0, -1e-3f, 0, 1}},        {8, 8, {0, 0, -100.0f, 1}},       {0, 11, {0.2f, 0.2f, 0.2f, -1.0f}},
};

gl::Texture plantedTexture() {
    auto t = gl::Texture::create2D(TextureFormat::RGBA32F, 12, 12, 1, "test.special values");
    std::vector<float> fill(12 * 12 * 4, 0.25f);
    for (std::size_t i = 3; i < fill.size(); i += 4) fill[i] = 1.0f;
    glTextureSubImage2D(t.name(), 0, 0, 0, 12, 12, GL_RGBA, GL_FLOAT, fill.data());
    for (const Planted& p : kPlanted)
        glTextureSubImage2D(t.name(), 0, p.x, p.y, 1, 1, GL_RGBA, GL_FLOAT, p.value);
    return t;
}

}  // namespace

class UiSpecialValues : public GlTest {};

TEST_F(UiSpecialValues, CountsMatchThePlantedTexels) {
    auto t = plantedTexture();
    TextureAnalyser analyser;
    ViewSettings settings = defaultViewSettings(t.spec());
    ASSERT_TRUE(analyser.update(textureSource(t), settings, 0.0));
    const TextureAnalysis& a = analyser.analysis();
    EXPECT_EQ(a.nanTexels, 3);
    EXPECT_EQ(a.infTexels, 2);
    EXPECT_EQ(a.negativeTexels, 4);
    // image_stats counts values per channel; the range covers the finite values only.
    EXPECT_EQ(a.stats[0].nanCount, 2);
    EXPECT_EQ(a.stats[0].min, -0.5f);
    EXPECT_EQ(a.stats[2].min, -100.0f);
    // A second update within the interval does not read again; a changed level or settings would.
    EXPECT_FALSE(analyser.update(textureSource(t), settings, 0.1));
    EXPECT_TRUE(analyser.update(textureSource(t), settings, 1.0));
}

TEST_F(UiSpecialValues, TheViewMarksEachKindInItsColour) {
    auto t = plantedTexture();
    TextureDisplay display;
    ASSERT_TRUE(display.ok()) << display.error();
    DisplaySurface surface("test.special surface");
    surface.resize(12, 12);
    ViewSettings s = defaultViewSettings(t.spec());
    s.highlightSpecial = true;
    display.draw(surface, textureSource(t), s, ViewWindow{});
    ByteImage shown = gl::readFramebufferRgba8(surface.framebuffer(), 12, 12);
    auto at = [&](int x, int y) {
        return std::array<int, 3>{shown.texel(x, y, 0), shown.texel(x, y, 1), shown.texel(x, y, 2)};
    };
    const std::array<int, 3> magenta{255, 0, 255}, amber{255, 199, 0}, azure{0, 171, 255};
    for (auto [x, y] : {std::pair{1, 1}, {7, 2}, {3, 9}}) EXPECT_EQ(at(x, y), magenta) << x << "," << y;
    for (auto [x, y] : {std::pair{10, 4}, {2, 6}}) EXPECT_EQ(at(x, y), amber) << x << "," << y;
    for (auto [x, y] : {std::pair{5, 5}, {6, 5}, {8, 8}, {0, 11}})
        EXPECT_EQ(at(x, y), azure) << x << "," << y;
    // Everything else is grey.
    auto plain = at(4, 4);
    EXPECT_EQ(plain[0], plain[1]);
    EXPECT_EQ(plain[1], plain[2]);
}

TEST_F(UiSpecialValues, DepthIsLinearisedWithTheCameraPlanes) {
    // Stored depth for distances 1 and 50 with near 0.5, far 100, as a perspective projection writes it.
    const float n = 0.5f, f = 100.0f;
    auto stored = [&](float z) { return (f + n - 2.0f * n * f / z) / (f - n) * 0.5f + 0.5f; };
    EXPECT_NEAR(linearizeDepth(stored(1.0f), n, f), 1.0f, 1e-4f);
    EXPECT_NEAR(linearizeDepth(stored(50.0f), n, f), 50.0f, 1e-2f);
    EXPECT_FLOAT_EQ(linearizeDepth(1.0f, n, f), f);
    EXPECT_FLOAT_EQ(linearizeDepth(0.0f, n, f), n);

    auto t = gl::Texture::create2D(TextureFormat::Depth32F, 2, 1, 1, "test.depth linear");
    float depth[2] = {stored(1.0f), stored(50.0f)};
    glTextureSubImage2D(t.name(), 0, 0, 0, 2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    ViewSettings s = defaultViewSettings(t.spec());
    s.cameraNear = n;
    s.cameraFar = f;
    TextureAnalyser analyser;
    ASSERT_TRUE(analyser.update(textureSource(t), s, 0.0));
    EXPECT_TRUE(analyser.analysis().linearDepth);
    EXPECT_NEAR(analyser.analysis().stats[0].min, 1.0f, 1e-3f);
    EXPECT_NEAR(analyser.analysis().stats[0].max, 50.0f, 0.05f);

    // Shown with the range [0, 100] (direct), 1 unit is nearly black and 50 units mid grey.
    TextureDisplay display;
    DisplaySurface surface("test.depth surface");
    surface.resize(2, 1);
    s.rangeLow = 0.0f;
    s.rangeHigh = 100.0f;
    display.draw(surface, textureSource(t), s, ViewWindow{});
    ByteImage shown = gl::readFramebufferRgba8(surface.framebuffer(), 2, 1);
    EXPECT_NEAR(shown.texel(0, 0, 0), 3, 1);
    EXPECT_NEAR(shown.texel(1, 0, 0), 128, 1);
}
