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

TEST(MipChain, RequestedLevelsAreClampedToTheChain) {
    TextureDesc full{TextureSize::output(), TextureFormat::RGBA16F, kFullMipChain};
    EXPECT_EQ(resolve(full, {1279, 719}).mipLevels, 11);
    EXPECT_EQ(resolve(full, {1, 1}).mipLevels, 1);
    TextureDesc six{TextureSize::output(), TextureFormat::RGBA16F, 6};
    EXPECT_EQ(resolve(six, {1280, 720}).mipLevels, 6);
    EXPECT_EQ(resolve(six, {4, 4}).mipLevels, 3);
}

}  // namespace
}  // namespace fx
