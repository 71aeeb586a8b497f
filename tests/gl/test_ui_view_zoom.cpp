// The inspector's view zoomed out, where one display pixel covers several texels, and each view
// transform (one program each, ui/texture_display.hpp): the texels of a pixel are averaged as light
// and encoded once, a special value anywhere in the footprint still marks the whole pixel, and every
// transform gives at one texel per pixel what the captures' CPU transform gives.
#include <cmath>
#include <limits>

#include "gl/readback.hpp"
#include "gl/texture.hpp"
#include "gl_test.hpp"
#include "image/view_transform.hpp"
#include "ui/texture_display.hpp"

using namespace fx;

namespace {

// A texture whose columns alternate between `a` and `b` (RGB alike, alpha 1).
gl::Texture stripes(int width, int height, float a, float b) {
    auto t = gl::Texture::create2D(TextureFormat::RGBA32F, width, height, 1, "test.view stripes");
    std::vector<float> texels;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            float v = x % 2 == 0 ? a : b;
            texels.insert(texels.end(), {v, v, v, 1.0f});
        }
    }
    glTextureSubImage2D(t.name(), 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, texels.data());
    return t;
}

// The first pixel of a view of `t` through `transform`, `texelsPerPixel` texels per pixel.
std::array<int, 3> firstPixel(const TextureDisplay& display, const gl::Texture& t, DisplayTransform transform,
                              double texelsPerPixel) {
    DisplaySurface surface("test.view zoom surface");
    surface.resize(1, 1);
    ViewSettings s = defaultViewSettings(t.spec());
    s.transform = transform;
    display.draw(surface, textureSource(t), s, ViewWindow{0.0, 0.0, texelsPerPixel});
    ByteImage shown = gl::readFramebufferRgba8(surface.framebuffer(), 1, 1);
    return {shown.texel(0, 0, 0), shown.texel(0, 0, 1), shown.texel(0, 0, 2)};
}

}  // namespace

class UiViewZoom : public GlTest {};

TEST_F(UiViewZoom, ZoomedOutPixelsAverageTheirTexelsAsLight) {
    TextureDisplay display;
    ASSERT_TRUE(display.ok()) << display.error();
    auto t = stripes(4, 4, 0.0f, 1.0f);
    // 2x2 texels a pixel: two black and two white, half the light.
    const int half = toDisplayValue(0.5f, ViewTransform::LinearToSrgb);
    EXPECT_EQ(firstPixel(display, t, DisplayTransform::Srgb, 2.0), (std::array<int, 3>{half, half, half}));
    // Averaging the encoded values instead would give 128, a much darker grey than half the light.
    EXPECT_GT(half, 180);
    const int direct = toDisplayValue(0.5f, ViewTransform::Direct);
    EXPECT_EQ(firstPixel(display, t, DisplayTransform::Direct, 2.0),
              (std::array<int, 3>{direct, direct, direct}));
    // Values above the range are clamped per texel before they are averaged: 4 and 0 are not 2 -> white.
    auto bright = stripes(4, 4, 0.0f, 4.0f);
    EXPECT_EQ(firstPixel(display, bright, DisplayTransform::Direct, 2.0),
              (std::array<int, 3>{direct, direct, direct}));
}

TEST_F(UiViewZoom, ASpecialValueAnywhereInTheFootprintMarksThePixel) {
    TextureDisplay display;
    ASSERT_TRUE(display.ok()) << display.error();
    auto t = stripes(4, 4, 0.25f, 0.5f);
    const float nan[4] = {std::nanf(""), 0.0f, 0.0f, 1.0f};
    glTextureSubImage2D(t.name(), 0, 3, 2, 1, 1, GL_RGBA, GL_FLOAT, nan);
    // 4x4 texels in one pixel: the NaN is one of 16 and still paints it magenta.
    for (DisplayTransform transform : {DisplayTransform::Direct, DisplayTransform::Srgb,
                                       DisplayTransform::Reinhard, DisplayTransform::FalseColour})
        EXPECT_EQ(firstPixel(display, t, transform, 4.0), (std::array<int, 3>{255, 0, 255}))
            << toString(transform);
}

TEST_F(UiViewZoom, EachTransformAtOneTexelPerPixel) {
    TextureDisplay display;
    ASSERT_TRUE(display.ok()) << display.error();
    auto t = stripes(1, 1, 0.5f, 0.5f);
    const int direct = toDisplayValue(0.5f, ViewTransform::Direct);
    const int srgb = toDisplayValue(0.5f, ViewTransform::LinearToSrgb);
    const int reinhard = toDisplayValue(0.5f / 1.5f, ViewTransform::LinearToSrgb);
    EXPECT_EQ(firstPixel(display, t, DisplayTransform::Direct, 1.0),
              (std::array<int, 3>{direct, direct, direct}));
    EXPECT_EQ(firstPixel(display, t, DisplayTransform::Srgb, 1.0), (std::array<int, 3>{srgb, srgb, srgb}));
    EXPECT_EQ(firstPixel(display, t, DisplayTransform::Reinhard, 1.0),
              (std::array<int, 3>{reinhard, reinhard, reinhard}));
    // The false-colour ramp at its middle: halfway between its green (0.10, 0.85, 0.62) and its
    // yellow (0.73, 0.95, 0.22) stops.
    auto ramp = firstPixel(display, t, DisplayTransform::FalseColour, 1.0);
    EXPECT_NEAR(ramp[0], 0.415 * 255, 1.0);
    EXPECT_NEAR(ramp[1], 0.90 * 255, 1.0);
    EXPECT_NEAR(ramp[2], 0.42 * 255, 1.0);
}
