#include <gtest/gtest.h>

#include "image/image.hpp"

namespace fx {
namespace {

TEST(Image, TexelsAreRowMajorBottomUpAndInterleaved) {
    FloatImage image = makeFloatImage(3, 2, 2, 0.0f);
    ASSERT_EQ(image.texels.size(), 12u);
    image.texel(2, 1, 1) = 7.0f;  // last texel of the top row, second channel
    EXPECT_EQ(image.texels.back(), 7.0f);
    image.texel(0, 0, 0) = 5.0f;  // first texel of the bottom row
    EXPECT_EQ(image.texels.front(), 5.0f);
    EXPECT_EQ(image.index(1, 1, 0), (1u * 3u + 1u) * 2u);
}

TEST(Image, FlipReversesRowsOnly) {
    ByteImage image = makeByteImage(2, 3, 1);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 2; ++x) image.texel(x, y, 0) = static_cast<std::uint8_t>(10 * y + x);
    const ByteImage flipped = flippedVertically(image);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 2; ++x) EXPECT_EQ(flipped.texel(x, 2 - y, 0), 10 * y + x);
}

TEST(Image, ToRgbaWidensLikeTheDisplay) {
    ByteImage grey = makeByteImage(1, 1, 1, 90);
    ByteImage rgba = toRgba(grey);
    EXPECT_EQ(rgba.channels, 4);
    EXPECT_EQ(rgba.texels, (std::vector<std::uint8_t>{90, 90, 90, 255}));

    ByteImage rg = makeByteImage(1, 1, 2);
    rg.texels = {10, 20};
    EXPECT_EQ(toRgba(rg).texels, (std::vector<std::uint8_t>{10, 20, 0, 255}));
}

TEST(Image, CheckShapeNamesTheProblem) {
    ByteImage image = makeByteImage(4, 4, 3);
    EXPECT_TRUE(checkShape(image, "capture").ok());
    image.texels.pop_back();
    Status status = checkShape(image, "capture");
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("capture"), std::string::npos);
    EXPECT_NE(status.error().find("4x4"), std::string::npos);

    ByteImage fiveChannels = makeByteImage(1, 1, 5);
    EXPECT_FALSE(checkShape(fiveChannels, "x").ok());
}

TEST(Image, ToFloatDividesBy255) {
    ByteImage image = makeByteImage(1, 1, 2);
    image.texels = {0, 255};
    const FloatImage f = toFloatImage(image);
    EXPECT_EQ(f.texels[0], 0.0f);
    EXPECT_EQ(f.texels[1], 1.0f);
}

}  // namespace
}  // namespace fx
