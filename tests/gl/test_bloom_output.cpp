// Lesson 06, step 5: the output transform's tone curves. The default (clip) is the chapters' picture
// and every other lesson's; Reinhard and the ACES-style filmic curve map HDR light into [0, 1], so
// 6 (a lamp) and 300 (the sun) no longer both come out as white. Read back as the presented bytes.
#include <cmath>

#include "effects/post/output_transform_pass.hpp"
#include "gl_test.hpp"
#include "test_fullscreen_harness.hpp"

using namespace fx;
using fx::test::EffectRunner;
using fx::test::makeImage;

namespace {

// The exact sRGB encoding of a linear value in [0, 1], as an 8-bit level.
int srgbLevel(float linear) {
    double c = std::clamp(double(linear), 0.0, 1.0);
    double e = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    return int(std::lround(e * 255.0));
}

class ToneCurveOnGl : public GlTest {};

}  // namespace

TEST_F(ToneCurveOnGl, CurvesMatchTheirFormulasAndKeepLampAndSunApart) {
    OutputTransformPass present;
    ASSERT_TRUE(programsBuilt());
    // Columns: 0.5, 1, 6 (a lamp), 300 (the sun), +Inf, NaN, -2.
    const float values[] = {0.5f, 1.0f, 6.0f, 300.0f, INFINITY, NAN, -2.0f};
    const int n = 7;
    FloatImage input = makeImage(n, 1, [&](int x, int) {
        float v = values[x];
        return std::array<float, 4>{v, v, v, 1.0f};
    });
    EffectRunner runner(n, 1);
    for (ToneCurve curve : {ToneCurve::clip, ToneCurve::reinhard, ToneCurve::filmic}) {
        runner.run(input, TextureFormat::RGBA32F, [&](FrameGraph& g, TextureHandle in) {
            present.declare(g, in, std::nullopt, curve);
            return in;
        });
        ASSERT_TRUE(runner.lastError.empty()) << runner.lastError;
        for (int x = 0; x < n; ++x) {
            // Inf counts as the largest half float; NaN and negatives as black. Without a curve a NaN
            // goes to the encoding as it is (the chapters' path, left unchanged), so it is not checked.
            if (std::isnan(values[x]) && curve == ToneCurve::clip) continue;
            float v = std::isnan(values[x]) ? 0.0f : values[x];
            int expected = srgbLevel(applyToneCurve(curve, v));
            EXPECT_NEAR(int(runner.presented.texel(x, 0, 0)), expected, 1)
                << toString(curve) << ", input " << values[x];
        }
        bool apart = runner.presented.texel(3, 0, 0) > runner.presented.texel(2, 0, 0);
        EXPECT_EQ(apart, curve != ToneCurve::clip) << toString(curve) << ": lamp and sun";
    }
    // The formulas themselves: Reinhard 1 -> 0.5; filmic 1 -> 2.54 / 3.16.
    EXPECT_FLOAT_EQ(applyToneCurve(ToneCurve::reinhard, 1.0f), 0.5f);
    EXPECT_NEAR(applyToneCurve(ToneCurve::filmic, 1.0f), 2.54f / 3.16f, 1e-6f);
    EXPECT_FLOAT_EQ(applyToneCurve(ToneCurve::clip, 6.0f), 1.0f);
}
