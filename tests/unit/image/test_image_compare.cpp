#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "image/image_compare.hpp"

namespace fx {
namespace {

TEST(ImageCompare, IdenticalImagesHaveInfinitePsnr) {
    FloatImage a = makeFloatImage(4, 3, 3, 0.25f);
    auto d = compare(a, a);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(d->rmse, 0.0);
    EXPECT_EQ(d->maxAbs, 0.0);
    EXPECT_EQ(d->differingTexels, 0);
    EXPECT_TRUE(std::isinf(d->psnr) && d->psnr > 0);
}

TEST(ImageCompare, OneFloatTexelOfKnownDifference) {
    FloatImage a = makeFloatImage(10, 10, 1, 0.5f), b = a;
    b.texel(3, 4, 0) = 0.5f + 0.4f;
    auto d = compare(a, b);
    ASSERT_TRUE(d.ok());
    const double diff = double(0.5f + 0.4f) - 0.5;
    const double mse = diff * diff / 100.0;
    EXPECT_NEAR(d->rmse, std::sqrt(mse), 1e-12);
    EXPECT_NEAR(d->maxAbs, diff, 1e-12);
    EXPECT_NEAR(d->psnr, 10.0 * std::log10(1.0 / mse), 1e-9);
    EXPECT_EQ(d->differingTexels, 1);
    EXPECT_EQ(d->nonFiniteTexels, 0);
}

TEST(ImageCompare, OneByteTexelOfKnownDifference) {
    ByteImage a = makeByteImage(4, 4, 4, 100), b = a;
    b.texel(1, 2, 0) = 110;
    b.texel(1, 2, 3) = 97;
    auto d = compare(a, b);
    ASSERT_TRUE(d.ok());
    const double mse = (10.0 * 10.0 + 3.0 * 3.0) / 64.0;
    EXPECT_NEAR(d->rmse, std::sqrt(mse), 1e-12);
    EXPECT_EQ(d->maxAbs, 10.0);
    EXPECT_NEAR(d->psnr, 10.0 * std::log10(255.0 * 255.0 / mse), 1e-9);
    EXPECT_EQ(d->differingTexels, 1);
}

TEST(ImageCompare, NanCountsAsUnboundedDifference) {
    FloatImage a = makeFloatImage(3, 1, 1, 0.0f), b = a;
    b.texels[1] = std::numeric_limits<float>::quiet_NaN();
    auto d = compare(a, b);
    ASSERT_TRUE(d.ok());
    EXPECT_FALSE(std::isnan(d->rmse));
    EXPECT_TRUE(std::isinf(d->rmse));
    EXPECT_TRUE(std::isinf(d->maxAbs));
    EXPECT_TRUE(std::isinf(d->psnr) && d->psnr < 0);
    EXPECT_EQ(d->nonFiniteTexels, 1);
    EXPECT_EQ(d->differingTexels, 1);

    // NaN on both sides is not "equal": a NaN is always reported.
    auto both = compare(b, b);
    ASSERT_TRUE(both.ok());
    EXPECT_EQ(both->nonFiniteTexels, 1);
}

TEST(ImageCompare, MatchingInfinitiesAreEqualAndMismatchedOnesAreNot) {
    const float inf = std::numeric_limits<float>::infinity();
    FloatImage a = makeFloatImage(2, 1, 1, inf), b = a;
    auto same = compare(a, b);
    ASSERT_TRUE(same.ok());
    EXPECT_EQ(same->rmse, 0.0);
    b.texels[0] = -inf;
    auto differ = compare(a, b);
    ASSERT_TRUE(differ.ok());
    EXPECT_EQ(differ->nonFiniteTexels, 1);
    EXPECT_TRUE(std::isinf(differ->rmse));
}

TEST(ImageCompare, ShapeMismatchNamesBothShapes) {
    auto d = compare(makeByteImage(4, 3, 4), makeByteImage(3, 4, 4));
    ASSERT_FALSE(d.ok());
    EXPECT_NE(d.error().find("4x3"), std::string::npos);
    EXPECT_NE(d.error().find("3x4"), std::string::npos);
    auto channels = compare(makeFloatImage(2, 2, 3), makeFloatImage(2, 2, 4));
    ASSERT_FALSE(channels.ok());
    EXPECT_NE(channels.error().find("3 channels"), std::string::npos);
}

TEST(ImageCompare, DifferencePictureMarksOnlyDifferingTexels) {
    ByteImage a = makeByteImage(4, 4, 3, 200), b = a;
    b.texel(2, 1, 1) = 201;  // the smallest possible difference must still stand out
    auto picture = differenceImage(a, b);
    ASSERT_TRUE(picture.ok());
    EXPECT_EQ(picture->channels, 4);
    const std::uint8_t* marked = &picture->texel(2, 1, 0);
    const std::uint8_t* plain = &picture->texel(0, 0, 0);
    EXPECT_GE(marked[0], 128);
    EXPECT_EQ(marked[1], 0);
    EXPECT_EQ(plain[0], plain[1]);  // grey
    EXPECT_LT(plain[0], 64);
}

}  // namespace
}  // namespace fx
