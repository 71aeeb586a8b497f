#include <gtest/gtest.h>

#include <cmath>

#include "image/plot_axis.hpp"

namespace fx {
namespace {

TEST(PlotAxis, NiceStepsAreOneTwoOrFiveTimesAPowerOfTen) {
    EXPECT_DOUBLE_EQ(niceStep(0.9), 1.0);
    EXPECT_DOUBLE_EQ(niceStep(1.3), 1.0);
    EXPECT_DOUBLE_EQ(niceStep(1.6), 2.0);
    EXPECT_DOUBLE_EQ(niceStep(4.0), 5.0);
    EXPECT_DOUBLE_EQ(niceStep(8.0), 10.0);
    EXPECT_NEAR(niceStep(0.0023), 0.002, 1e-15);
    EXPECT_DOUBLE_EQ(niceStep(370.0), 500.0);
}

TEST(PlotAxis, LinearTicksCoverTheDataOnNiceNumbers) {
    const PlotAxis axis = makeLinearAxis(0.3, 9.7, 6);
    EXPECT_LT(axis.low, 0.3);
    EXPECT_GT(axis.high, 9.7);
    ASSERT_GE(axis.ticks.size(), 4u);
    ASSERT_EQ(axis.ticks.size(), axis.tickLabels.size());
    const double step = axis.ticks[1] - axis.ticks[0];
    EXPECT_DOUBLE_EQ(step, 2.0);
    for (double tick : axis.ticks) {
        EXPECT_GE(tick, axis.low);
        EXPECT_LE(tick, axis.high);
        EXPECT_NEAR(std::remainder(tick, step), 0.0, 1e-9);
    }
    EXPECT_EQ(axis.tickLabels[0], "0");
    EXPECT_EQ(axis.tickLabels[1], "2");
}

TEST(PlotAxis, FractionalTicksGetJustEnoughDecimals) {
    const PlotAxis axis = makeLinearAxis(0.0, 1.0, 5);
    ASSERT_FALSE(axis.tickLabels.empty());
    EXPECT_EQ(axis.tickLabels[1], "0.2");
    EXPECT_EQ(formatTick(0.30000000000000004, 0.1), "0.3");
    EXPECT_EQ(formatTick(-1e-17, 0.1), "0.0");
    EXPECT_EQ(formatTick(0.025, 0.005), "0.025");
    EXPECT_EQ(formatTick(1e-6, 1e-6), "1e-6");
    EXPECT_EQ(formatTick(2e7, 1e6), "2e7");
}

TEST(PlotAxis, SingleValueGetsARangeAroundIt) {
    const PlotAxis axis = makeLinearAxis(3.0, 3.0);
    EXPECT_LT(axis.low, 3.0);
    EXPECT_GT(axis.high, 3.0);
    EXPECT_GE(axis.ticks.size(), 2u);
    const PlotAxis zero = makeLinearAxis(0.0, 0.0);
    EXPECT_LT(zero.low, 0.0);
    EXPECT_GT(zero.high, 0.0);
}

TEST(PlotAxis, LogTicksAreDecades) {
    const PlotAxis axis = makeLogAxis(1e-4, 0.5);
    EXPECT_TRUE(axis.logarithmic);
    EXPECT_LT(axis.low, 1e-4);
    EXPECT_GT(axis.high, 0.5);
    std::vector<std::string> expected = {"0.0001", "0.001", "0.01", "0.1"};
    EXPECT_EQ(axis.tickLabels, expected);
    EXPECT_NEAR(axis.fraction(std::sqrt(axis.low * axis.high)), 0.5, 1e-12);
}

TEST(PlotAxis, NarrowLogRangeAddsTwosAndFives) {
    const PlotAxis axis = makeLogAxis(0.011, 0.04);
    ASSERT_GE(axis.ticks.size(), 3u);
    for (double tick : axis.ticks) {
        const double mantissa = tick / std::pow(10.0, std::floor(std::log10(tick) + 1e-9));
        EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
                    std::abs(mantissa - 5) < 1e-9)
            << tick;
    }
}

}  // namespace
}  // namespace fx
