// Bloom chain sizes and widths (effects/bloom/bloom_levels.hpp): the chapters' tables, odd sizes, and levels
// that would be smaller than a texel.
#include <cmath>

#include <gtest/gtest.h>

#include "effects/bloom/bloom_levels.hpp"

using namespace fx;

namespace {

std::vector<Size2D> sizes(const std::vector<BloomLevel>& levels) {
    std::vector<Size2D> out;
    for (auto& l : levels) out.push_back(l.size);
    return out;
}

}  // namespace

TEST(BloomLevels, ShaderEffectsChapterQuarterChainAt1080p) {
    // The Shader effects chapter's numbers: 480x270, 240x135, 120x67, 60x33, 30x16, 15x8.
    auto levels = bloomLevels({1920, 1080}, 4, 6);
    std::vector<Size2D> expected{{480, 270}, {240, 135}, {120, 67}, {60, 33}, {30, 16}, {15, 8}};
    EXPECT_EQ(sizes(levels), expected);
    EXPECT_EQ(levels[5].divisor, 128);
}

TEST(BloomLevels, BloomChapterHalfChainAt720p) {
    // Bloom chapter §1.3, levels 1..6: 640x360 .. 20x11 (45 -> 22 -> 11: not exact halvings).
    auto levels = bloomLevels({1280, 720}, 2, 6);
    std::vector<Size2D> expected{{640, 360}, {320, 180}, {160, 90}, {80, 45}, {40, 22}, {20, 11}};
    EXPECT_EQ(sizes(levels), expected);
}

TEST(BloomLevels, LevelsBelowOneTexelAreNotCreated) {
    EXPECT_TRUE(bloomLevels({0, 0}, 2, 6).empty()) << "a minimised window has no chain";
    EXPECT_TRUE(bloomLevels({1, 1}, 2, 6).empty()) << "half of 1x1 is 0x0";
    EXPECT_TRUE(bloomLevels({3, 1}, 2, 6).empty());
    EXPECT_EQ(bloomLevels({2, 2}, 2, 6).size(), 1u);
    // 63x63: a quarter is 15, then 7, 3, 1 and then nothing.
    std::vector<Size2D> expected{{15, 15}, {7, 7}, {3, 3}, {1, 1}};
    EXPECT_EQ(sizes(bloomLevels({63, 63}, 4, 6)), expected);
    // 1279x719 halves to 639x359 .. 19x11 and stops at the requested count.
    auto odd = bloomLevels({1279, 719}, 2, 8);
    ASSERT_EQ(odd.size(), 8u);
    EXPECT_EQ(odd.back().size, (Size2D{4, 2}));
    // The count is clamped to 1..kBloomMaxLevels.
    EXPECT_EQ(bloomLevels({4096, 4096}, 2, 100).size(), std::size_t(kBloomMaxLevels));
    EXPECT_EQ(bloomLevels({64, 64}, 2, 0).size(), 1u);
}

TEST(BloomLevels, EveryLevelMatchesTheFrameGraphsFraction) {
    // The chain declares outputFraction(1, divisor): it must resolve to the same size, so no level
    // is ever made larger by the graph's never-below-one rule.
    for (Size2D output : {Size2D{1279, 719}, Size2D{63, 63}, Size2D{1, 640}, Size2D{333, 2}}) {
        for (auto& l : bloomLevels(output, 4, 8)) {
            EXPECT_EQ(TextureSize::outputFraction(1, l.divisor).resolve(output), l.size);
        }
    }
}

TEST(BloomLevels, FilterVariancesOfTheChapters) {
    // The Bloom chapter's 4 diagonal taps at 0.75 texel are the [1 3 3 1]/8 binomial: variance 0.75.
    EXPECT_NEAR(bloomDownsampleVariance(0.75), 0.75, 1e-12);
    // The dual-filter upsample at 0.5: taps 4/3 * 0.25 plus bilinear 3/16 at every tap.
    EXPECT_NEAR(bloomUpsampleVariance(0.5), 1.0 / 3.0 + 3.0 / 16.0, 1e-12);
    // Widths grow about twofold per level.
    double previous = 0;
    for (int level = 0; level < 8; ++level) {
        double sigma = bloomLevelSigma(level, 0.75, 0.5);
        if (level > 0) {
            EXPECT_GT(sigma / previous, 1.8);
            EXPECT_LT(sigma / previous, 2.25);  // sqrt(5) from level 0 to 1, then towards 2
        }
        previous = sigma;
    }
    EXPECT_NEAR(bloomLevelSigma(0, 0.75, 0.5), std::sqrt(0.75 + 4 * (1.0 / 3.0 + 3.0 / 16.0)), 1e-12);
}
