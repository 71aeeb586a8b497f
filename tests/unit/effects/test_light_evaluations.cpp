// How often the point-light formula runs (Deferred rendering chapter, hard case 20): W x H x N without
// culling, and after tiled culling each tile's pixels (partial tiles at the edges) times its list.
#include <gtest/gtest.h>

#include "effects/deferred/light_evaluations.hpp"
#include "effects/deferred/tiled_culling.hpp"

namespace {

using namespace fx;

TEST(LightEvaluations, NaiveIsWidthTimesHeightTimesLights) {
    EXPECT_EQ(naiveLightEvaluations({1920, 1080}, 1024), 2123366400);  // 2.1 billion a frame
    EXPECT_EQ(naiveLightEvaluations({320, 180}, 256), 14745600);
    EXPECT_EQ(naiveLightEvaluations({1, 1}, 1), 1);
    EXPECT_EQ(naiveLightEvaluations({0, 0}, 1024), 0);  // minimised
    EXPECT_EQ(naiveLightEvaluations({320, 180}, 0), 0);
}

TEST(LightEvaluations, TiledCountsEachTilesPixelsTimesItsLights) {
    // 40 x 20: tiles of 16 x 16, 3 x 2 of them; the right column is 8 wide, the top row 4 high.
    const Size2D size{40, 20};
    ASSERT_EQ(tileCount(size), (Size2D{3, 2}));
    const std::vector<float> lights = {1, 2, 3, 4, 5, 6};
    EXPECT_EQ(tiledLightEvaluations(size, lights),
              16 * 16 * 1 + 16 * 16 * 2 + 8 * 16 * 3 + 16 * 4 * 4 + 16 * 4 * 5 + 8 * 4 * 6);
    // Every tile listing every light is the naive count again.
    EXPECT_EQ(tiledLightEvaluations(size, std::vector<float>(6, 7.0f)), naiveLightEvaluations(size, 7));
    // A list shorter than the tiles counts what it has; negative counts count as none.
    EXPECT_EQ(tiledLightEvaluations(size, {1}), 16 * 16);
    EXPECT_EQ(tiledLightEvaluations(size, {-3, 1}), 16 * 16);
}

}  // namespace
