// The frame budget: an automatic picture scale gives way to keep a slow frame within the budget and
// comes back when the frames are cheap; a pinned one never moves.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "app/picture_scale.hpp"

namespace fx {
namespace {

// A made-up renderer: `fixedMs` whatever the size (the overlay, the CPU) plus `fullMs` for the whole
// picture, in proportion to its pixels.
double frameMs(const PictureScale& s, double fixedMs, double fullMs) {
    return fixedMs + fullMs * s.scale() * s.scale();
}

TEST(PictureScale, AFastRendererKeepsTheWholePicture) {
    PictureScale s;
    for (int i = 0; i < 50; ++i) s.frameTook(frameMs(s, 10, 40));
    EXPECT_EQ(s.scale(), 1.0);
    EXPECT_EQ(s.notice({896, 504}), "");
}

TEST(PictureScale, ASlowRendererSettlesWithinTheBudget) {
    // Lesson 10's many lights on llvmpipe: 3 s a frame at full size.
    PictureScale s;
    std::vector<double> last;
    for (int i = 0; i < 60; ++i) {
        const double ms = frameMs(s, 20, 3000);
        s.frameTook(ms);
        last.push_back(ms);
    }
    EXPECT_LT(s.scale(), 0.3);
    EXPECT_GE(s.scale(), 0.1);
    for (std::size_t i = last.size() - 10; i < last.size(); ++i) EXPECT_LE(last[i], kFrameBudgetMs);
    // It gives way at the first very slow frame after the one it skips: the second frame is cheaper.
    PictureScale fresh;
    fresh.frameTook(3000);
    fresh.frameTook(3000);
    EXPECT_LT(fresh.scale(), 0.5);
    EXPECT_NE(s.notice({896, 504}).find("slow renderer"), std::string::npos) << s.notice({896, 504});
}

TEST(PictureScale, ComesBackWhenTheFramesAreCheapAgain) {
    PictureScale s;
    for (int i = 0; i < 30; ++i) s.frameTook(frameMs(s, 20, 3000));
    const double slow = s.scale();
    for (int i = 0; i < 200; ++i) s.frameTook(frameMs(s, 10, 40));  // the next step is cheap
    EXPECT_GT(s.scale(), slow);
    EXPECT_EQ(s.scale(), 1.0);
}

TEST(PictureScale, DoesNotSwingBetweenTwoScales) {
    PictureScale s;
    std::vector<double> scales;
    for (int i = 0; i < 300; ++i) {
        s.frameTook(frameMs(s, 30, 400));
        scales.push_back(s.scale());
    }
    int changes = 0;
    for (std::size_t i = 200; i < scales.size(); ++i) changes += scales[i] != scales[i - 1];
    EXPECT_EQ(changes, 0) << "settled at " << s.scale();
}

TEST(PictureScale, AFrameWhoseTimeIsNotInItsPixelsKeepsItsPicture) {
    // Lesson 02's crowd on a loaded software renderer: 500 ms of skinning whatever the size, 60 of pixels.
    PictureScale s;
    for (int i = 0; i < 80; ++i) s.frameTook(frameMs(s, 500, 60));
    EXPECT_GE(s.scale(), 0.7) << "a smaller picture would save at most 60 ms of 560";
    const PictureScale::Cost c = s.cost();
    EXPECT_NEAR(c.fixed, 500, 5);
    EXPECT_NEAR(c.pixels, 60, 5);
    if (s.scale() < 1.0) {
        EXPECT_NE(s.notice({896, 504}).find("not in its pixels"), std::string::npos) << s.notice({896, 504});
    }
    // Half fixed, half pixels: it goes down only as far as the pixels can give.
    PictureScale half;
    for (int i = 0; i < 80; ++i) half.frameTook(frameMs(half, 120, 300));
    const double ms = frameMs(half, 120, 300);
    EXPECT_LE(ms, kFrameBudgetMs);
    EXPECT_GT(half.scale(), 0.3) << "120 ms fixed leave room for a third of the pixels";
}

TEST(PictureScale, NoisyFramesStillSettleWithinTheBudget) {
    // A shared machine: every frame up to 20% off, the same way each run (a fixed pattern).
    const double noise[] = {1.0, 1.18, 0.86, 1.05, 0.93, 1.2, 0.82, 1.1, 0.97, 1.14, 0.88};
    PictureScale s;
    std::vector<double> frames;
    for (int i = 0; i < 200; ++i) {
        const double ms = frameMs(s, 30, 1500) * noise[i % 11];
        s.frameTook(ms);
        frames.push_back(frameMs(s, 30, 1500));
    }
    std::sort(frames.begin() + 100, frames.end());
    EXPECT_LE(frames[150], kFrameBudgetMs) << "the median of the second half, without the noise";
    EXPECT_GT(s.scale(), 0.2);
}

TEST(PictureScale, PinnedNeverMovesAndTheKeyCycles) {
    PictureScale s(0.4);
    for (int i = 0; i < 20; ++i) s.frameTook(5000);
    EXPECT_DOUBLE_EQ(s.scale(), 0.4);
    EXPECT_NE(s.notice({896, 504}).find("pinned"), std::string::npos);
    EXPECT_EQ(s.rendered({896, 504}), (Size2D{358, 202}));
    s.cycle();  // 40% is at or below 50%: on to 25%
    EXPECT_DOUBLE_EQ(s.scale(), 0.25);
    s.cycle();
    EXPECT_TRUE(s.automatic());
    s.cycle();
    EXPECT_DOUBLE_EQ(s.scale(), 1.0);
    EXPECT_FALSE(s.automatic());
}

TEST(PictureScale, NeverBelowOnePixel) {
    PictureScale s(0.1);
    EXPECT_EQ(s.rendered({3, 1}), (Size2D{1, 1}));
    EXPECT_TRUE(s.rendered({0, 0}).empty());
}

}  // namespace
}  // namespace fx
