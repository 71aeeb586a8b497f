#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "image/image_stats.hpp"

namespace fx {
namespace {

TEST(ImageStats, CountsPlantedValuesPerChannel) {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    FloatImage image = makeFloatImage(4, 2, 2, 0.5f);
    // Channel 0: two NaN, one +Inf, one -Inf, one negative (-2), one -0.0 (not negative), large 8.
    image.texel(0, 0, 0) = nan;
    image.texel(1, 0, 0) = nan;
    image.texel(2, 0, 0) = inf;
    image.texel(3, 0, 0) = -inf;
    image.texel(0, 1, 0) = -2.0f;
    image.texel(1, 1, 0) = -0.0f;
    image.texel(2, 1, 0) = 8.0f;
    // Channel 1 stays 0.5 except one value.
    image.texel(3, 1, 1) = 1.5f;

    const std::vector<ChannelStats> stats = computeStats(image);
    ASSERT_EQ(stats.size(), 2u);
    EXPECT_EQ(stats[0].nanCount, 2);
    EXPECT_EQ(stats[0].infCount, 2);
    EXPECT_EQ(stats[0].negativeCount, 1);
    EXPECT_EQ(stats[0].finiteCount, 4);
    EXPECT_EQ(stats[0].min, -2.0f);
    EXPECT_EQ(stats[0].max, 8.0f);
    EXPECT_DOUBLE_EQ(stats[0].mean, (-2.0 + 0.0 + 8.0 + 0.5) / 4.0);

    EXPECT_EQ(stats[1].nanCount, 0);
    EXPECT_EQ(stats[1].infCount, 0);
    EXPECT_EQ(stats[1].negativeCount, 0);
    EXPECT_EQ(stats[1].min, 0.5f);
    EXPECT_EQ(stats[1].max, 1.5f);
    EXPECT_DOUBLE_EQ(stats[1].mean, (7 * 0.5 + 1.5) / 8.0);
}

TEST(ImageStats, AllNonFiniteLeavesZeroRange) {
    FloatImage image = makeFloatImage(2, 1, 1, std::numeric_limits<float>::quiet_NaN());
    const auto stats = computeStats(image);
    ASSERT_EQ(stats.size(), 1u);
    EXPECT_EQ(stats[0].finiteCount, 0);
    EXPECT_EQ(stats[0].nanCount, 2);
    EXPECT_EQ(stats[0].min, 0.0f);
    EXPECT_EQ(stats[0].max, 0.0f);
    EXPECT_EQ(stats[0].mean, 0.0);
}

TEST(ImageStats, FlatnessHonoursTolerance) {
    ByteImage image = makeByteImage(8, 8, 4, 30);
    EXPECT_TRUE(isFlat(image, 0));
    image.texel(5, 6, 2) = 33;
    EXPECT_FALSE(isFlat(image, 2));
    EXPECT_TRUE(isFlat(image, 3));
    EXPECT_TRUE(isFlat(ByteImage{}, 0));
}

TEST(ImageStats, FlatnessComparesEachChannelWithItsOwn) {
    // A uniform colour whose channels differ from each other is still flat.
    ByteImage image = makeByteImage(3, 3, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x) {
            image.texel(x, y, 0) = 200;
            image.texel(x, y, 1) = 10;
            image.texel(x, y, 2) = 90;
        }
    EXPECT_TRUE(isFlat(image, 0));
}

}  // namespace
}  // namespace fx
