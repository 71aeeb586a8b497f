// What the generated textures must look like, measured: the cloud density against the statistics of
// the Clouds chapter's cloud density, the fire sprite's alpha against Shader effects §3.8, seamless tiling.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "hash_noise.hpp"
#include "textures.hpp"

namespace {

using fx::ByteImage;

float value(const ByteImage& image, int x, int y, int channel = 0) {
    return image.texel(x, y, channel) / 255.0f;
}

// Mean absolute difference (in 0..255 steps) between column x0 and x1 of channel c.
double columnStep(const ByteImage& image, int x0, int x1, int c = 0) {
    double sum = 0;
    for (int y = 0; y < image.height; ++y)
        sum += std::abs(int(image.texel(x0, y, c)) - int(image.texel(x1, y, c)));
    return sum / image.height;
}
double rowStep(const ByteImage& image, int y0, int y1, int c = 0) {
    double sum = 0;
    for (int x = 0; x < image.width; ++x)
        sum += std::abs(int(image.texel(x, y0, c)) - int(image.texel(x, y1, c)));
    return sum / image.width;
}

class CloudDensity : public ::testing::Test {
protected:
    static void SetUpTestSuite() { image_ = new ByteImage(fx::assetgen::cloudDensity()); }
    static void TearDownTestSuite() {
        delete image_;
        image_ = nullptr;
    }
    static ByteImage* image_;

    static std::vector<float> sortedValues() {
        std::vector<float> v;
        for (auto t : image_->texels) v.push_back(t / 255.0f);
        std::sort(v.begin(), v.end());
        return v;
    }
    // Autocorrelation at a lag of `lag` texels, along rows and columns (wrapping: the texture tiles).
    static double autocorrelation(int lag) {
        const ByteImage& im = *image_;
        double mean = 0;
        for (auto t : im.texels) mean += t;
        mean /= double(im.texels.size());
        double covariance = 0, variance = 0;
        for (int y = 0; y < im.height; ++y) {
            for (int x = 0; x < im.width; ++x) {
                double a = im.texel(x, y, 0) - mean;
                double right = im.texel((x + lag) % im.width, y, 0) - mean;
                double up = im.texel(x, (y + lag) % im.height, 0) - mean;
                covariance += a * (right + up) / 2;
                variance += a * a;
            }
        }
        return covariance / variance;
    }
};
ByteImage* CloudDensity::image_ = nullptr;

TEST_F(CloudDensity, IsA512SquareGreyImage) {
    EXPECT_EQ(image_->width, 512);
    EXPECT_EQ(image_->height, 512);
    EXPECT_EQ(image_->channels, 1);  // R = G = B and opaque when read as RGBA
}

TEST_F(CloudDensity, ValueStatisticsMatchTheCloudsChapter) {
    auto v = sortedValues();
    auto quantile = [&](double q) { return v[std::size_t(q * double(v.size() - 1))]; };
    double mean = 0, squares = 0;
    for (float x : v) mean += x;
    mean /= double(v.size());
    for (float x : v) squares += (x - mean) * (x - mean);
    double sd = std::sqrt(squares / double(v.size()));
    // Clouds chapter: mean 0.447, sd 0.18, quantiles 0.12 / 0.33 / 0.47 / 0.58 / 0.71, max 230.
    EXPECT_NEAR(mean, 0.447, 0.01);
    EXPECT_NEAR(sd, 0.18, 0.015);
    EXPECT_NEAR(quantile(0.05), 0.12, 0.01);
    EXPECT_NEAR(quantile(0.25), 0.33, 0.01);
    EXPECT_NEAR(quantile(0.5), 0.47, 0.01);
    EXPECT_NEAR(quantile(0.75), 0.58, 0.01);
    EXPECT_NEAR(quantile(0.95), 0.71, 0.01);
    EXPECT_LE(*std::max_element(image_->texels.begin(), image_->texels.end()), 230);
    EXPECT_LT(std::count_if(v.begin(), v.end(), [](float x) { return x > 0.85f; }),
              std::ptrdiff_t(v.size() / 50));
}

TEST_F(CloudDensity, TilesWithoutASeam) {
    // Across the wrap the step is about the same as between neighbours inside (the chapter: 3.7 and 4.5
    // at the seam, 3.0 and 3.3 inside, out of 255).
    const ByteImage& im = *image_;
    double inside = 0;
    for (int x = 0; x + 1 < im.width; ++x) inside += columnStep(im, x, x + 1);
    inside /= im.width - 1;
    EXPECT_LT(columnStep(im, im.width - 1, 0), 1.5 * inside + 0.5);
    EXPECT_LT(rowStep(im, im.height - 1, 0), 1.5 * inside + 0.5);
    EXPECT_GT(inside, 1.5);  // there is fine detail to compare
    EXPECT_LT(inside, 6.0);
}

TEST_F(CloudDensity, BlobsAreFortyToSixtyTexelsAcross) {
    // The chapter's autocorrelation: 0.84 at 8 texels, 0.55 at 16, about 0.1 at 32, about 0 at 40.
    EXPECT_NEAR(autocorrelation(8), 0.84, 0.06);
    EXPECT_NEAR(autocorrelation(16), 0.55, 0.1);
    EXPECT_NEAR(autocorrelation(32), 0.1, 0.12);
    EXPECT_NEAR(autocorrelation(40), 0.0, 0.1);
    EXPECT_LT(autocorrelation(64), 0.05);
}

TEST_F(CloudDensity, CoverageDependsOnTheColourSpaceAsTheChapterMeasured) {
    // The Clouds chapter's part 4: the sum of two independent samples against threshold 0.5 covers
    // about 30 % of the sky when the texture is sampled sRGB-decoded (as the lesson stores it), and
    // about 93 % when the stored values are read raw.
    const ByteImage& im = *image_;
    auto decode = [](float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); };
    std::size_t decodedCovered = 0, rawCovered = 0, n = 0;
    double decodedMean = 0;
    for (int y = 0; y < im.height; y += 2) {
        for (int x = 0; x < im.width; x += 2) {
            // Two far-apart texels stand for the two layers at unrelated scales.
            float a = value(im, x, y), b = value(im, (x + 173) % im.width, (y + 311) % im.height);
            decodedCovered += decode(a) + decode(b) > 0.5f;
            rawCovered += a + b > 0.5f;
            decodedMean += decode(a);
            ++n;
        }
    }
    EXPECT_NEAR(double(decodedCovered) / double(n), 0.30, 0.05);
    EXPECT_NEAR(double(rawCovered) / double(n), 0.93, 0.04);
    EXPECT_NEAR(decodedMean / double(n), 0.203, 0.02);  // the chapter's decoded mean
}

TEST(FireSprite, AlphaIsAnUprightSoftTeardrop) {
    ByteImage sprite = fx::assetgen::fireSprite();
    ASSERT_EQ(sprite.channels, 4);
    ASSERT_EQ(sprite.width, 256);
    const int w = sprite.width, h = sprite.height;
    auto alpha = [&](float u, float v) {
        return value(sprite, std::min(int(u * w), w - 1), std::min(int(v * h), h - 1), 3);
    };
    // Transparent border: nothing reaches the edges of the quad.
    for (int i = 0; i < w; ++i) {
        EXPECT_EQ(sprite.texel(i, 0, 3), 0);
        EXPECT_EQ(sprite.texel(i, h - 1, 3), 0);
        EXPECT_EQ(sprite.texel(0, i, 3), 0);
        EXPECT_EQ(sprite.texel(w - 1, i, 3), 0);
    }
    // Opaque core on the axis from the base up to the upper body; v = 0 is the bottom row.
    for (float v : {0.15f, 0.27f, 0.5f, 0.7f}) EXPECT_GT(alpha(0.5f, v), 0.95f) << "v = " << v;
    EXPECT_LT(alpha(0.5f, 0.02f), 0.05f);  // below the round base
    EXPECT_LT(alpha(0.5f, 0.98f), 0.05f);  // above the tip
    // Wide at the base, narrow near the tip: the flame points up, not down.
    auto width = [&](float v) {
        int n = 0;
        for (int x = 0; x < w; ++x) n += alpha((x + 0.5f) / w, v) > 0.5f;
        return n;
    };
    EXPECT_GT(width(0.27f), 3 * width(0.85f));
    EXPECT_GT(width(0.27f), w / 4);
    // Soft edge: between the opaque core and the outside there are partial values.
    int partial = 0;
    for (int x = 0; x < w; ++x) {
        float a = alpha((x + 0.5f) / w, 0.27f);
        partial += a > 0.05f && a < 0.95f;
    }
    EXPECT_GE(partial, 4);
}

TEST(GroundChecker, IsAColourCheckerThatTiles) {
    ByteImage checker = fx::assetgen::groundChecker();
    ASSERT_EQ(checker.width, 256);
    ASSERT_EQ(checker.channels, 3);
    // Two tones: the first cell is light, its neighbour dark.
    EXPECT_GT(checker.texel(16, 16, 0), checker.texel(48, 16, 0) + 60);
    // The wrap is a cell border like any other inside: a grout line on both sides.
    EXPECT_NEAR(columnStep(checker, 255, 0), columnStep(checker, 31, 32), 3.0);
    EXPECT_NEAR(rowStep(checker, 255, 0), rowStep(checker, 31, 32), 3.0);
}

TEST(HashNoise, GradientNoiseRepeatsWithItsPeriod) {
    for (float x : {0.1f, 1.7f, 3.25f}) {
        for (float y : {0.3f, 2.9f}) {
            float a = fx::assetgen::tileableGradientNoise(x, y, 4, 7u);
            EXPECT_NEAR(a, fx::assetgen::tileableGradientNoise(x + 4.0f, y, 4, 7u), 1e-5f);
            EXPECT_NEAR(a, fx::assetgen::tileableGradientNoise(x, y - 4.0f, 4, 7u), 1e-5f);
            EXPECT_LE(std::abs(a), 1.01f);
        }
    }
    EXPECT_EQ(fx::assetgen::tileableGradientNoise(2.0f, 3.0f, 4, 7u), 0.0f);  // zero on lattice points
}

TEST(HashNoise, HashIsFixedAndWellSpread) {
    // Fixed values: a change here changes every generated texture.
    EXPECT_EQ(fx::assetgen::hash32(0u), 0u);
    EXPECT_NE(fx::assetgen::hash32(1u), fx::assetgen::hash32(2u));
    int ones = 0;
    for (std::uint32_t i = 0; i < 1024; ++i)
        ones += __builtin_popcount(fx::assetgen::hash32(i) ^ fx::assetgen::hash32(i ^ 1u));
    EXPECT_NEAR(ones / 1024.0, 16.0, 1.5);  // flipping one input bit flips about half the output bits
}

}  // namespace

TEST(CutoutLattice, AlphaIsZeroOrOneWithSquareHolesThatTile) {
    ByteImage lattice = fx::assetgen::cutoutLattice();
    ASSERT_EQ(lattice.width, 128);
    ASSERT_EQ(lattice.height, 128);
    ASSERT_EQ(lattice.channels, 4);
    int holes = 0;
    for (int y = 0; y < lattice.height; ++y) {
        for (int x = 0; x < lattice.width; ++x) {
            int a = lattice.texel(x, y, 3);
            ASSERT_TRUE(a == 0 || a == 255) << "a partly transparent texel at " << x << "," << y;
            holes += a == 0 ? 1 : 0;
            // Tiles: the same 64-texel cell everywhere, so the edges meet without a seam.
            EXPECT_EQ(a, lattice.texel(x % 64, y % 64, 3));
        }
    }
    // 2x2 holes of 48x48 texels: 9/16 of the texture is hole.
    EXPECT_EQ(holes, 4 * 48 * 48);
    EXPECT_EQ(lattice.texel(32, 32, 3), 0);   // a hole's centre
    EXPECT_EQ(lattice.texel(0, 32, 3), 255);  // a bar on the cell border
}
