// The Depth of field chapter's numbers in lesson 09's shaders, read back as floats. A colour that is a
// linear ramp in x and y turns a blur into a measurement: every tap reads its own position, so the
// output minus the centre's position is the taps' mean offset. That gives the naive blur's scale
// ((d - 0.935) x 0.1 in texture coordinates: 0.0065 for the sky, -0.0435 at raw depth 0.5), the same
// in u and v and so elliptical in pixels, and different for the same distance under another near/far
// (hard case 12); and the Poisson disk's off-centre mean (0.030, -0.105), which moves strongly blurred
// content by about (0.028, -0.097) x the radius (hard case 11).
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "base/paths.hpp"
#include "effects/dof/depth_of_field.hpp"
#include "gl_test.hpp"
#include "test_fullscreen_harness.hpp"

using namespace fx;
using fx::test::EffectRunner;
using fx::test::makeImage;

namespace {

// The 12 taps of the shaders' Poisson disk, read from shaders/effects/dof/poisson.glsl.
std::vector<glm::vec2> poissonTaps() {
    std::ifstream file(shaderDir() / "effects/dof/poisson.glsl");
    std::stringstream text;
    text << file.rdbuf();
    const std::string source = text.str();
    std::vector<glm::vec2> taps;
    const std::regex tap(R"(vec2\((-?[0-9.]+), (-?[0-9.]+)\))");
    for (auto it = std::sregex_iterator(source.begin(), source.end(), tap); it != std::sregex_iterator();
         ++it)
        taps.emplace_back(std::stof((*it)[1]), std::stof((*it)[2]));
    return taps;
}

glm::vec2 tapSum() {
    glm::vec2 sum(0.0f);
    for (glm::vec2 p : poissonTaps()) sum += p;
    return sum;
}

class DofChapterNumbers : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        ASSERT_TRUE(programsBuilt());
    }
    // The pass `declare` makes on a ramp (r = x, g = y, in the units `unit` gives a pixel) with every
    // depth `depth`; returns the output at the centre pixel, where the input is 0: the taps' mean offset.
    glm::vec2 shiftAtCentre(
        int w, int h, glm::vec2 unit, float depth,
        const std::function<TextureHandle(FrameGraph&, TextureHandle, TextureHandle)>& declare) {
        // 0 at the centre pixel, where the output (a half float) is read: there it has bits to spare.
        const int cx = w / 2, cy = h / 2;
        FloatImage ramp = makeImage(w, h, [=](int x, int y) {
            return std::array<float, 4>{float(x - cx) * unit.x, float(y - cy) * unit.y, 0.0f, 1.0f};
        });
        std::vector<float> depths(std::size_t(w) * std::size_t(h), depth);
        gl::Texture depthTexture = gl::Texture::create2D(TextureFormat::R32F, w, h, 1, "test.depth");
        glTextureSubImage2D(depthTexture.name(), 0, 0, 0, w, h, GL_RED, GL_FLOAT, depths.data());
        EffectRunner runner(w, h);
        FloatImage out = runner.run(ramp, TextureFormat::RGBA32F, [&](FrameGraph& g, TextureHandle in) {
            TextureHandle d =
                g.importTexture("test.depth", {w, h, TextureFormat::R32F, 1}, depthTexture.name());
            return declare(g, in, d);
        });
        EXPECT_TRUE(runner.lastError.empty()) << runner.lastError;
        if (out.texels.empty()) return glm::vec2(NAN);
        return {out.texel(cx, cy, 0), out.texel(cx, cy, 1)};
    }
    // The naive pass's scale in texture coordinates, from u and from v.
    glm::vec2 naiveScale(int w, int h, float depth) {
        glm::vec2 shift = shiftAtCentre(w, h, {1.0f / float(w), 1.0f / float(h)}, depth,
                                        [&](FrameGraph& g, TextureHandle in, TextureHandle d) {
                                            return effect.declareNaive(g, in, d, NaiveDofSettings{}).output;
                                        });
        return shift * 13.0f / tapSum();  // 13 taps averaged, the centre adds nothing
    }
    DepthOfField effect;
};

}  // namespace

TEST(DofPoissonDisk, TwelveTapsWithRadii051To099AndAMeanOff0030Minus0105) {
    std::vector<glm::vec2> taps = poissonTaps();
    ASSERT_EQ(taps.size(), 12u);
    float shortest = 2.0f, longest = 0.0f;
    for (glm::vec2 p : taps) {
        shortest = std::min(shortest, glm::length(p));
        longest = std::max(longest, glm::length(p));
    }
    EXPECT_NEAR(shortest, 0.511f, 0.001f);
    EXPECT_NEAR(longest, 0.992f, 0.001f);
    EXPECT_NEAR(tapSum().x / 12.0f, 0.030f, 0.001f);
    EXPECT_NEAR(tapSum().y / 12.0f, -0.105f, 0.001f);
}

TEST_F(DofChapterNumbers, TheNaiveScaleIsRawDepthMinus0935TimesATenthTheSameInUAndV) {
    // The lesson's naive step: near 1 m, far 1000 m. The player at 15.264 m writes 0.9354 (sharp), the
    // old camera's 55.9 m writes 0.9831 (nothing in focus at the first checkpoint).
    EXPECT_NEAR(windowDepth(15.264, 1.0, 1000.0), 0.9354, 5e-5);
    EXPECT_NEAR(windowDepth(55.9, 1.0, 1000.0), 0.9831, 5e-5);
    EXPECT_NEAR(linearDepthM(0.5, 1.0, 1000.0), 2.0, 0.005);  // raw depth 0.5 is about 2 m
    const int w = 64, h = 36;
    for (float d : {1.0f, 0.5f, 0.9831f, 0.935f}) {
        glm::vec2 scale = naiveScale(w, h, d);
        const float expected = (d - 0.935f) * 0.1f;
        EXPECT_NEAR(scale.x, expected, 2e-4f) << "from u at depth " << d;
        EXPECT_NEAR(scale.y, expected, 2e-4f) << "from v at depth " << d;
    }
    EXPECT_NEAR(naiveScale(w, h, 1.0f).y, 0.0065f, 2e-4f);   // the sky: about 8 px across 1280
    EXPECT_NEAR(naiveScale(w, h, 0.5f).y, -0.0435f, 2e-4f);  // 2 m: about 55 px across 1280
    // One scale in texture coordinates is two in pixels: 1280 across, 720 down (an ellipse).
    EXPECT_NEAR(0.0065f * 1280.0f, 8.3f, 0.05f);
    EXPECT_NEAR(0.0065f * 720.0f, 4.7f, 0.05f);
}

TEST_F(DofChapterNumbers, TheNaiveBlurOfOneDistanceDependsOnNearAndFar) {
    // 2 m from the camera: -0.0435 with near 1 and far 1000, but +0.0015 with near 0.1 and far 500
    // (the depth it writes is 0.9502): the same object blurs the other way, less.
    const float tuned = float(windowDepth(2.0, 1.0, 1000.0)), other = float(windowDepth(2.0, 0.1, 500.0));
    EXPECT_NEAR(other, 0.9502f, 5e-4f);
    EXPECT_NEAR(naiveScale(64, 36, tuned).y, -0.0435f, 2e-4f);
    EXPECT_NEAR(naiveScale(64, 36, other).y, (0.9502f - 0.935f) * 0.1f, 2e-4f);
}

TEST_F(DofChapterNumbers, ThePoissonDisksMeanMovesAStrongBlurByAboutATenthOfItsRadiusDown) {
    // The chapter's physical pass with one CoC everywhere (the chapter's lens, its diameter used as
    // the radius): the taps reach radius x p_i pixels, and their mean is off centre.
    ThinLensInput in;
    in.lens = Lens{31.1769f, 36.0f, 1.4f, 15.264f};
    in.nearM = 1.0f;
    in.farM = 500.0f;
    in.widthPixels = 1280;  // the chapter's pixels per millimetre: about 23 px at 1 m
    in.maxCocPixels = 1.0e6f;
    in.convention = CocConvention::chapter;
    ThinLensModel model = thinLensModel(in);
    const float depth = float(windowDepth(1.0, 1.0, 500.0)) + 0.0005f;  // just beyond the near plane
    const float radius = float(std::abs(signedCocPixelsFromDepth(model, depth)) * model.radiusPerDiameter);
    ASSERT_GT(radius, 15.0f);
    ASSERT_LT(radius, 30.0f);  // every tap inside the 64 x 64 picture
    DofLensUniforms lens = dofLensUniforms(model);
    glm::vec2 shift =
        shiftAtCentre(64, 64, {1.0f, 1.0f}, depth, [&](FrameGraph& g, TextureHandle c, TextureHandle d) {
            return effect.declareChapter(g, c, effect.declareCoc(g, d, lens).output, lens).output;
        });
    // The 12 taps' mean is (0.030, -0.105); with the centre it is (0.028, -0.097) x the radius.
    EXPECT_NEAR(shift.x / radius, 0.028f, 0.002f);
    EXPECT_NEAR(shift.y / radius, -0.097f, 0.002f);
}
