#include <gtest/gtest.h>

#include "base/texture_spec.hpp"

namespace fx {
namespace {

TEST(MipChain, FullLength) {
    EXPECT_EQ(fullMipChainLength(1, 1), 1);
    EXPECT_EQ(fullMipChainLength(2, 1), 2);
    EXPECT_EQ(fullMipChainLength(1279, 719), 11);
    EXPECT_EQ(fullMipChainLength(1280, 720), 11);
    EXPECT_EQ(fullMipChainLength(1024, 1024), 11);
    EXPECT_EQ(fullMipChainLength(1023, 5), 10);
    EXPECT_EQ(fullMipChainLength(0, 0), 1);
    EXPECT_EQ(mipLevelSize(1279, 1), 639);
    EXPECT_EQ(mipLevelSize(719, 10), 1);
    EXPECT_EQ(mipLevelSize(5, 40), 1);
}

TEST(MipChain, LevelSizeOfASpec) {
    TextureSpec spec{1279, 719, TextureFormat::RGBA16F, 11};
    EXPECT_EQ(spec.levelSize(0), (Size2D{1279, 719}));
    EXPECT_EQ(spec.levelSize(2), (Size2D{319, 179}));
    EXPECT_EQ(spec.levelSize(10), (Size2D{1, 1}));
    EXPECT_EQ((TextureSpec{0, 0, TextureFormat::RGBA8, 1}.levelSize(3)), (Size2D{0, 0}));
}

TEST(TextureBytes, FullChainOfAnOddSize) {
    // Levels of 1279x719: 1279x719, 639x359, 319x179, 159x89, 79x44, 39x22, 19x11, 9x5, 4x2, 2x1, 1x1
    // = 1,224,853 texels at 8 bytes (RGBA16F).
    TextureSpec spec{1279, 719, TextureFormat::RGBA16F, 11};
    EXPECT_EQ(textureBytes(spec), 9'798'824u);
    EXPECT_EQ(textureBytes({1279, 719, TextureFormat::RGBA16F, 1}), 1279u * 719u * 8u);
    EXPECT_EQ(textureBytes({2048, 2048, TextureFormat::Depth32F, 1}), 16'777'216u);
    EXPECT_EQ(textureBytes({0, 0, TextureFormat::RGBA8, 1}), 0u);
}

TEST(TextureSpec, DescribesItself) {
    EXPECT_EQ(toString(TextureSpec{319, 179, TextureFormat::RGBA16F, 9}), "319x179 RGBA16F, 9 mips");
    EXPECT_EQ(toString(TextureSpec{1, 1, TextureFormat::R8, 1}), "1x1 R8, 1 mip");
}

TEST(Size2D, DescribesItself) {
    EXPECT_EQ(toString(Size2D{1279, 719}), "1279x719");
    EXPECT_TRUE((Size2D{0, 720}).empty());
    EXPECT_FALSE((Size2D{1, 1}).empty());
}

}  // namespace
}  // namespace fx
