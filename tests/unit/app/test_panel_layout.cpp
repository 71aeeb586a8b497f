// The presentation layout: the picture is never under a panel, and every panel stays on the window,
// at every size and every share a settings file or a drag can give.
#include <gtest/gtest.h>

#include <limits>

#include "ui/panel_layout.hpp"

namespace {

using fx::LayoutRect;
using fx::LayoutShares;

void expectInside(const LayoutRect& r, int w, int h, const char* what) {
    EXPECT_TRUE(r.inside(float(w), float(h))) << what << " at " << r.x << "," << r.y << " " << r.width << "x"
                                              << r.height << " in " << w << "x" << h;
    EXPECT_GE(r.width, 0.0f) << what;
    EXPECT_GE(r.height, 0.0f) << what;
}

}  // namespace

TEST(PanelLayout, ThePictureIsUnderNoPanelAndEveryPanelIsOnTheWindow) {
    const int sizes[][2] = {{1280, 720}, {1920, 1080}, {1024, 768}, {800, 600},  {320, 180},
                            {200, 900},  {1, 1},       {0, 0},      {3840, 2160}};
    const LayoutShares shares[] = {{}, {0.0f, 0.0f, 0.0f}, {5.0f, 5.0f, 5.0f}, {0.6f, 0.2f, 0.8f}};
    for (auto [w, h] : sizes) {
        for (const LayoutShares& s : shares) {
            for (bool inspectorOpen : {false, true}) {
                for (float scale : {1.0f, 3.0f}) {
                    SCOPED_TRACE(testing::Message() << w << "x" << h << " inspector " << inspectorOpen
                                                    << " scale " << scale << " column share " << s.column);
                    auto l = fx::computePanelLayout(w, h, s, inspectorOpen, 19.0f * scale, 300.0f * scale);
                    expectInside(l.picture, w, h, "picture");
                    expectInside(l.lesson, w, h, "lesson");
                    expectInside(l.frame, w, h, "frame");
                    expectInside(l.inspector, w, h, "inspector");
                    for (const LayoutRect* panel : {&l.lesson, &l.frame, &l.inspector})
                        EXPECT_FALSE(l.picture.overlaps(*panel));
                    EXPECT_FALSE(l.lesson.overlaps(l.frame));
                    EXPECT_FALSE(l.lesson.overlaps(l.inspector));
                    EXPECT_FALSE(l.frame.overlaps(l.inspector));
                    // The picture keeps at least 40% of the width, whatever the text scale.
                    if (w > 0) {
                        EXPECT_GE(l.picture.width, 0.4f * float(w) - 1.0f);
                    }
                }
            }
        }
    }
}

TEST(PanelLayout, AtProjectorSizesThePictureIsMostOfTheWindow) {
    // Without the inspector the picture takes everything but the column.
    auto l = fx::computePanelLayout(1280, 720, {}, false, 19.0f, 300.0f);
    EXPECT_EQ(l.picture.x, 384.0f);
    EXPECT_EQ(l.picture.width, 896.0f);
    EXPECT_EQ(l.picture.height, 720.0f);
    // The collapsed inspector is a title bar at the column's foot.
    EXPECT_EQ(l.inspector.height, 19.0f);
    EXPECT_EQ(l.inspector.bottom(), 720.0f);
    // Open, it takes the lower part of the rest and the picture the upper.
    auto open = fx::computePanelLayout(1280, 720, {}, true, 19.0f, 300.0f);
    EXPECT_EQ(open.picture.height + open.inspector.height, 720.0f);
    EXPECT_EQ(open.inspector.x, open.picture.x);
}

TEST(PanelLayout, SharesFromAFileAreBroughtIntoRange) {
    auto s = fx::clampShares({std::numeric_limits<float>::quiet_NaN(), -1.0f, 9.0f});
    EXPECT_EQ(s.column, LayoutShares{}.column);
    EXPECT_EQ(s.lesson, 0.2f);
    EXPECT_EQ(s.picture, 0.8f);
}

TEST(PanelLayout, ThePictureKeepsItsAspectInsideItsPlace) {
    // The default 1280x720 window: the place beside the column is 896x720, the 16:9 picture 896x504.
    auto l = fx::computePanelLayout(1280, 720, {}, false, 19.0f, 300.0f);
    LayoutRect p = fx::keepAspect(l.picture, 16.0 / 9.0);
    EXPECT_EQ(p.x, 384.0f);
    EXPECT_EQ(p.y, 108.0f);
    EXPECT_EQ(p.width, 896.0f);
    EXPECT_EQ(p.height, 504.0f);
    // A wide place: bars left and right.
    p = fx::keepAspect({10, 20, 1000, 100}, 16.0 / 9.0);
    EXPECT_EQ(p.height, 100.0f);
    EXPECT_EQ(p.width, 178.0f);
    EXPECT_EQ(p.x, 10.0f + 411.0f);
    // Free: the place as it is; tiny places keep a pixel.
    EXPECT_EQ(fx::keepAspect({5, 6, 70, 80}, 0.0).width, 70.0f);
    p = fx::keepAspect({0, 0, 1, 1}, 16.0 / 9.0);
    EXPECT_EQ(p.width, 1.0f);
    EXPECT_EQ(p.height, 1.0f);
    EXPECT_EQ(fx::keepAspect({0, 0, 0, 0}, 16.0 / 9.0).width, 0.0f);
    // Every size of the sweep: inside its place and at the aspect to within a pixel.
    for (int w : {1, 7, 333, 896, 1920}) {
        for (int h : {1, 5, 504, 720, 1080}) {
            const LayoutRect place{3, 4, float(w), float(h)};
            const LayoutRect r = fx::keepAspect(place, 16.0 / 9.0);
            EXPECT_GE(r.x, place.x);
            EXPECT_GE(r.y, place.y);
            EXPECT_LE(r.right(), place.right());
            EXPECT_LE(r.bottom(), place.bottom());
            EXPECT_TRUE(r.width == place.width || r.height == place.height) << w << "x" << h;
            if (r.width > 16 && r.height > 9) {
                EXPECT_NEAR(r.width / r.height, 16.0 / 9.0, 2.0 / r.height);
            }
        }
    }
}
