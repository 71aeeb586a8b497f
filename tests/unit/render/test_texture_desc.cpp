#include <gtest/gtest.h>

#include "render/texture_desc.hpp"

namespace fx {
namespace {

TEST(TextureSize, FractionsFloorLikeMipLevels) {
    Size2D out{1279, 719};
    EXPECT_EQ(TextureSize::outputFraction(1, 4).resolve(out), (Size2D{319, 179}));
    EXPECT_EQ(TextureSize::outputFraction(1, 2).resolve(out), (Size2D{639, 359}));
    EXPECT_EQ(TextureSize::output().resolve(out), out);
    EXPECT_EQ(TextureSize::outputFraction(2, 3).resolve(out), (Size2D{852, 479}));
    // 1/2^k of the output is exactly mip level k of the output.
    for (int k = 0; k < 12; ++k) {
        Size2D s = TextureSize::outputFraction(1, 1 << k).resolve(out);
        EXPECT_EQ(s.width, mipLevelSize(out.width, k)) << k;
        EXPECT_EQ(s.height, mipLevelSize(out.height, k)) << k;
    }
}

TEST(TextureSize, NeverBelowOneForANonZeroOutput) {
    EXPECT_EQ(TextureSize::outputFraction(1, 64).resolve({1, 1}), (Size2D{1, 1}));
    EXPECT_EQ(TextureSize::outputFraction(1, 4).resolve({3, 1000}), (Size2D{1, 250}));
    // Only the zero axis stays zero.
    EXPECT_EQ(TextureSize::outputFraction(1, 4).resolve({0, 720}), (Size2D{0, 180}));
}

TEST(TextureSize, ZeroOutputAndZeroDenominatorDoNotDivide) {
    EXPECT_EQ(TextureSize::outputFraction(1, 4).resolve({0, 0}), (Size2D{0, 0}));
    EXPECT_EQ(TextureSize::outputFraction(1, 0).resolve({1280, 720}), (Size2D{0, 0}));
    EXPECT_EQ(TextureSize::absolute(2048, 2048).resolve({0, 0}), (Size2D{2048, 2048}));
}

TEST(TextureSize, DescribesItself) {
    EXPECT_EQ(toString(TextureSize::outputFraction(1, 4)), "1/4 output");
    EXPECT_EQ(toString(TextureSize::output()), "output");
    EXPECT_EQ(toString(TextureSize::absolute(2048, 1024)), "2048x1024");
}

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

TEST(MipChain, RequestedLevelsAreClampedToTheChain) {
    TextureDesc full{TextureSize::output(), TextureFormat::RGBA16F, kFullMipChain};
    EXPECT_EQ(resolve(full, {1279, 719}).mipLevels, 11);
    EXPECT_EQ(resolve(full, {1, 1}).mipLevels, 1);
    TextureDesc six{TextureSize::output(), TextureFormat::RGBA16F, 6};
    EXPECT_EQ(resolve(six, {1280, 720}).mipLevels, 6);
    EXPECT_EQ(resolve(six, {4, 4}).mipLevels, 3);
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

}  // namespace
}  // namespace fx
