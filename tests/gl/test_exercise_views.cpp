// The picture view's two-picture drawing as an exercise's views use it (F3 on an exercise's step): a
// probe's numbers become colours by the exercise's display scale and offset, NaN and Inf are magenta, the
// difference is |second - first| * scale * gain, and a tiny probe result keeps its aspect, scaled up by a
// whole number and centred on the ground. The step compare's split draws through the same code.
#include <array>
#include <cmath>
#include <limits>

#include "gl/framebuffer.hpp"
#include "gl/readback.hpp"
#include "gl/texture.hpp"
#include "gl_test.hpp"
#include "ui/picture_view.hpp"

using namespace fx;

namespace {

// A float picture of `width` x 1 texels, each texel's red, green and blue the same value.
gl::Texture floatPicture(const std::vector<float>& values, const char* label) {
    gl::Texture texture = gl::Texture::create2D(TextureFormat::RGBA32F, int(values.size()), 1, 1, label);
    std::vector<float> texels;
    for (float v : values) texels.insert(texels.end(), {v, v, v, 1.0f});
    glTextureSubImage2D(texture.name(), 0, 0, 0, int(values.size()), 1, GL_RGBA, GL_FLOAT, texels.data());
    return texture;
}

struct Drawn {
    ByteImage pixels;
    LayoutRect at;
    // The red, green and blue of the window pixel (x, y), y from the top as LayoutRect counts.
    std::array<int, 3> rgb(int x, int y) const {
        const int row = pixels.height - 1 - y;
        return {pixels.texel(x, row, 0), pixels.texel(x, row, 1), pixels.texel(x, row, 2)};
    }
};

class ExerciseViews : public GlTest {
protected:
    // Draws the pair into a `width` x `height` window-like target, the place all of it.
    Drawn draw(int width, int height, PairView view, const gl::Texture& first, const gl::Texture& second,
               const PairDisplay& display) {
        gl::ColorDepthTarget window =
            gl::ColorDepthTarget::create(width, height, "test.window", "test window");
        const LayoutRect place{0, 0, float(width), float(height)};
        Drawn out;
        out.at = picture.drawPair(window.framebuffer.name(), height, place, view, first, second, display);
        out.pixels = gl::readFramebufferRgba8(window.framebuffer.name(), width, height);
        return out;
    }
    PictureView picture;
};

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
const std::array<int, 3> kMagenta = {255, 0, 255};

}  // namespace

TEST_F(ExerciseViews, TheDisplayScaleMapsKnownValuesToKnownColours) {
    // Exercise 09-1's display: value x 1/64 + 0.5, so a CoC of 0 px is grey, +32 px white, -32 px black.
    const gl::Texture values =
        floatPicture({0.0f, 16.0f, -32.0f, 64.0f, kNaN, kInf, -kInf, 8.0f}, "test.values");
    const PairDisplay display{1.0f / 64.0f, 0.5f, kDifferenceGain, true};
    const Drawn d = draw(8, 1, PairView::First, values, values, display);
    const int expected[] = {128, 191, 0, 255};  // 0.5, 0.75, 0 (-0.0), 1 (clamped from 1.5)
    for (int x = 0; x < 4; ++x) {
        SCOPED_TRACE(x);
        for (int c : d.rgb(x, 0)) EXPECT_NEAR(c, expected[x], 1);
    }
    for (int x = 4; x < 7; ++x) EXPECT_EQ(d.rgb(x, 0), kMagenta) << "NaN and Inf are magenta, texel " << x;
    for (int c : d.rgb(7, 0)) EXPECT_NEAR(c, 159, 1);  // 8 / 64 + 0.5 = 0.625
}

TEST_F(ExerciseViews, TheDifferenceIsScaledByTheDisplayAndTheGainAndBlackWhereTheyAgree) {
    const gl::Texture student = floatPicture({1.0f, 3.0f, 0.25f, kNaN}, "test.student");
    const gl::Texture reference = floatPicture({1.0f, 1.0f, 0.0f, 1.0f}, "test.reference");
    const PairDisplay display{0.125f, 0.5f, kDifferenceGain, true};
    const Drawn d = draw(4, 1, PairView::Difference, student, reference, display);
    EXPECT_EQ(d.rgb(0, 0), (std::array<int, 3>{0, 0, 0})) << "equal values: black, whatever the offset";
    EXPECT_EQ(d.rgb(1, 0), (std::array<int, 3>{255, 255, 255})) << "|3 - 1| x 0.125 x 8 = 2, clamped";
    for (int c : d.rgb(2, 0)) EXPECT_NEAR(c, 64, 1);  // 0.25 x 0.125 x 8 = 0.25
    EXPECT_EQ(d.rgb(3, 0), kMagenta) << "a NaN of the student's shows in the difference";
}

TEST_F(ExerciseViews, ATinyProbeResultKeepsItsAspectOnWholePixelsCentredOnTheGround) {
    // One texel: a 40x40 square in the middle of a 100x40 place, the rest ground.
    const gl::Texture one = floatPicture({1.0f}, "test.one");
    const Drawn d = draw(100, 40, PairView::First, one, one, PairDisplay{1.0f, 0.0f, kDifferenceGain, true});
    EXPECT_EQ(d.at.x, 30.0f);
    EXPECT_EQ(d.at.y, 0.0f);
    EXPECT_EQ(d.at.width, 40.0f);
    EXPECT_EQ(d.at.height, 40.0f);
    EXPECT_EQ(d.rgb(30, 0), (std::array<int, 3>{255, 255, 255}));
    EXPECT_EQ(d.rgb(69, 39), (std::array<int, 3>{255, 255, 255}));
    EXPECT_EQ(d.rgb(29, 20), (std::array<int, 3>{20, 20, 23})) << "the ground left of the picture";
    EXPECT_EQ(d.rgb(70, 20), (std::array<int, 3>{20, 20, 23})) << "the ground right of the picture";

    // 17x3 (exercise 09-1's odd case) in a 1280x720 place: 75 screen pixels a texel, centred.
    const LayoutRect strip = fitPicture({17, 3}, {10, 20, 1280, 720});
    EXPECT_EQ(strip.width, 17.0f * 75.0f);
    EXPECT_EQ(strip.height, 3.0f * 75.0f);
    EXPECT_EQ(strip.x, 10.0f + 2.0f);
    EXPECT_EQ(strip.y, 20.0f + std::floor((720.0f - 225.0f) / 2.0f));
    // Larger than its place: shrunk to fit, aspect kept.
    const LayoutRect large = fitPicture({2000, 1000}, {0, 0, 1000, 1000});
    EXPECT_EQ(large.width, 1000.0f);
    EXPECT_EQ(large.height, 500.0f);
}

TEST_F(ExerciseViews, WithoutAStudentsPictureThePlaceIsGround) {
    // A student's file that did not build leaves no picture: ground, not a stale or undefined one.
    const gl::Texture reference = floatPicture({1.0f, 1.0f}, "test.reference");
    const Drawn d = draw(8, 4, PairView::Difference, gl::Texture{}, reference,
                         PairDisplay{1.0f, 0.0f, kDifferenceGain, true});
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) EXPECT_EQ(d.rgb(x, y), (std::array<int, 3>{20, 20, 23})) << x << "," << y;
}
