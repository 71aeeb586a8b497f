#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "image/view_transform.hpp"

namespace fx {
namespace {

// The sRGB encoding written out again here, independently of the code under test.
int expectedSrgbByte(double linear) {
    const double encoded = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
    return static_cast<int>(std::floor(encoded * 255.0 + 0.5));
}

TEST(ViewTransform, SrgbEncodesKnownValues) {
    EXPECT_EQ(toDisplayValue(0.5f, ViewTransform::LinearToSrgb), 188);  // not 186 (gamma 2.2), not 128
    EXPECT_EQ(toDisplayValue(0.2126f, ViewTransform::LinearToSrgb), expectedSrgbByte(0.2126));
    EXPECT_EQ(expectedSrgbByte(0.2126), 127);
    EXPECT_EQ(toDisplayValue(0.0f, ViewTransform::LinearToSrgb), 0);
    EXPECT_EQ(toDisplayValue(1.0f, ViewTransform::LinearToSrgb), 255);
    // On the linear toe of the curve: 0.002 * 12.92 * 255 = 6.59.
    EXPECT_EQ(toDisplayValue(0.002f, ViewTransform::LinearToSrgb), 7);
    for (float v : {0.001f, 0.01f, 0.05f, 0.18f, 0.33f, 0.75f, 0.9f})
        EXPECT_EQ(toDisplayValue(v, ViewTransform::LinearToSrgb), expectedSrgbByte(v)) << "linear " << v;
}

TEST(ViewTransform, DirectScalesAndRoundsToNearest) {
    EXPECT_EQ(toDisplayValue(0.5f, ViewTransform::Direct), 128);  // 127.5 rounds up
    EXPECT_EQ(toDisplayValue(0.25f, ViewTransform::Direct), 64);  // 63.75
    EXPECT_EQ(toDisplayValue(1.0f / 255.0f, ViewTransform::Direct), 1);
    EXPECT_EQ(toDisplayValue(-3.0f, ViewTransform::Direct), 0);
    EXPECT_EQ(toDisplayValue(7.0f, ViewTransform::Direct), 255);
}

TEST(ViewTransform, NonFiniteValuesStayVisible) {
    const float inf = std::numeric_limits<float>::infinity();
    FloatImage image = makeFloatImage(3, 1, 3);
    image.texels = {std::nanf(""), 0.5f, 0.5f,   // NaN in one channel: the whole texel is magenta
                    inf,           inf,  inf,    // +Inf clamps to white
                    -inf,          0.0f, -inf};  // -Inf clamps to black
    const ByteImage display = toDisplay(image, ViewTransform::LinearToSrgb);
    EXPECT_EQ(display.channels, 4);
    EXPECT_EQ(std::vector<std::uint8_t>(display.texels.begin(), display.texels.begin() + 4),
              (std::vector<std::uint8_t>{255, 0, 255, 255}));
    EXPECT_EQ(std::vector<std::uint8_t>(display.texels.begin() + 4, display.texels.begin() + 8),
              (std::vector<std::uint8_t>{255, 255, 255, 255}));
    EXPECT_EQ(std::vector<std::uint8_t>(display.texels.begin() + 8, display.texels.end()),
              (std::vector<std::uint8_t>{0, 0, 0, 255}));
}

TEST(ViewTransform, FewerChannelsExpandToRgbWithOpaqueAlpha) {
    FloatImage grey = makeFloatImage(1, 1, 1, 0.5f);
    EXPECT_EQ(toDisplay(grey, ViewTransform::Direct).texels, (std::vector<std::uint8_t>{128, 128, 128, 255}));

    FloatImage rg = makeFloatImage(1, 1, 2);
    rg.texels = {1.0f, 0.25f};
    EXPECT_EQ(toDisplay(rg, ViewTransform::Direct).texels, (std::vector<std::uint8_t>{255, 64, 0, 255}));
}

TEST(ViewTransform, AlphaIsNeverSrgbEncoded) {
    FloatImage rgba = makeFloatImage(1, 1, 4);
    rgba.texels = {0.5f, 0.5f, 0.5f, 0.5f};
    EXPECT_EQ(toDisplay(rgba, ViewTransform::LinearToSrgb).texels,
              (std::vector<std::uint8_t>{188, 188, 188, 128}));
}

TEST(ViewTransform, KeepsBottomUpOrder) {
    FloatImage image = makeFloatImage(1, 2, 1);
    image.texel(0, 0, 0) = 1.0f;  // bottom row white
    const ByteImage display = toDisplay(image, ViewTransform::Direct);
    EXPECT_EQ(display.texel(0, 0, 0), 255);
    EXPECT_EQ(display.texel(0, 1, 0), 0);
}

}  // namespace
}  // namespace fx
