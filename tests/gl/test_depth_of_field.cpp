// Depth of field (effects/dof): the shader's circle of confusion against the CPU thin lens
// (scene/thin_lens.hpp) read back as floats, and the Depth of field chapter's hard cases: the focus at
// or inside the focal length, f-number 0, extreme fields of view, the sky, the focus plane itself,
// depths beyond far, a CoC far larger than the kernel, and odd and tiny sizes.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include <unistd.h>

#include <glm/geometric.hpp>

#include "effects/dof/depth_of_field.hpp"
#include "effects/dof/dof_bindings.hpp"
#include "effects/dof/dof_reference.hpp"
#include "gl_test.hpp"
#include "test_fullscreen_harness.hpp"

using namespace fx;
using fx::test::EffectRunner;
using fx::test::makeImage;

namespace {

ThinLensInput chapterCamera(CocConvention convention, float maxCoc = 1.0e6f) {
    ThinLensInput in;
    in.lens = Lens{31.1769f, 36.0f, 1.4f, 15.264f};
    in.nearM = 0.5f;
    in.farM = 500.0f;
    in.widthPixels = 1280;
    in.maxCocPixels = maxCoc;
    in.convention = convention;
    return in;
}

FloatImage uniformColour(int w, int h, std::array<float, 4> c) {
    return makeImage(w, h, [c](int, int) { return c; });
}

class DepthOfFieldOnGl : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        ASSERT_TRUE(programsBuilt());
    }

    // Runs `declare` on `colour` (RGBA32F) with a depth texture (R32F) filled by depth(x, y).
    FloatImage run(int w, int h, const FloatImage& colour, const std::function<float(int, int)>& depth,
                   const std::function<TextureHandle(FrameGraph&, TextureHandle, TextureHandle)>& declare) {
        std::vector<float> depths(std::size_t(w) * std::size_t(h));
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                depths[std::size_t(y) * std::size_t(w) + std::size_t(x)] = depth(x, y);
        gl::Texture depthTexture = gl::Texture::create2D(TextureFormat::R32F, w, h, 1, "test.depth");
        glTextureSubImage2D(depthTexture.name(), 0, 0, 0, w, h, GL_RED, GL_FLOAT, depths.data());
        EffectRunner runner(w, h);
        FloatImage out = runner.run(colour, TextureFormat::RGBA32F, [&](FrameGraph& g, TextureHandle in) {
            TextureHandle d =
                g.importTexture("test.depth", {w, h, TextureFormat::R32F, 1}, depthTexture.name());
            return declare(g, in, d);
        });
        lastError = runner.lastError;
        return out;
    }

    FloatImage coc(int w, int h, const ThinLensModel& model, const std::function<float(int, int)>& depth) {
        DofLensUniforms lens = dofLensUniforms(model);
        return run(w, h, uniformColour(w, h, {0, 0, 0, 1}), depth,
                   [&](FrameGraph& g, TextureHandle, TextureHandle d) {
                       return effect.declareCoc(g, d, lens).output;
                   });
    }

    DepthOfField effect;
    std::string lastError;
};

}  // namespace

TEST_F(DepthOfFieldOnGl, CocMatchesTheCpuThinLensAtAHundredDistances) {
    // 99 distances from the near plane (0.5 m) to the far plane, evenly spaced in 1/D (as the CoC is),
    // and the sky (depth 1).
    for (CocConvention convention : {CocConvention::corrected, CocConvention::chapter}) {
        ThinLensModel model = thinLensModel(chapterCamera(convention));
        std::vector<float> depths;
        for (int i = 0; i < 99; ++i) {
            double inverse = 1.0 / 0.5 + (1.0 / 500.0 - 1.0 / 0.5) * i / 98.0;
            depths.push_back(float(windowDepth(1.0 / inverse, 0.5, 500.0)));
        }
        depths.push_back(1.0f);
        FloatImage out = coc(100, 1, model, [&](int x, int) { return depths[std::size_t(x)]; });
        ASSERT_FALSE(out.empty()) << lastError;
        double worst = 0;
        for (int x = 0; x < 100; ++x) {
            double cpu = signedCocPixelsFromDepth(model, depths[std::size_t(x)]);
            worst = std::max(worst, std::abs(double(out.texel(x, 0, 0)) - cpu));
        }
        EXPECT_LE(worst, 1e-3) << (convention == CocConvention::chapter ? "chapter" : "corrected");
    }
}

TEST_F(DepthOfFieldOnGl, SkyFocusPlaneAndBeyondFar) {
    ThinLensModel model = thinLensModel(chapterCamera(CocConvention::chapter, 32.0f));
    const float atFocus = float(windowDepth(15.264, 0.5, 500.0));
    const float values[] = {1.0f, atFocus, 1.5f, 1e30f, -0.5f, 0.0f};
    FloatImage out = coc(6, 1, model, [&](int x, int) { return values[x]; });
    ASSERT_FALSE(out.empty()) << lastError;
    ASSERT_TRUE(allFinite(out));
    // The sky is the far plane: a finite CoC (the chapter's 1.57 px at 1280 wide, hard case 9).
    EXPECT_NEAR(out.texel(0, 0, 0), signedCocPixelsFromDepth(model, 1.0), 1e-3);
    EXPECT_GT(out.texel(0, 0, 0), 1.5f);
    // The focus plane: no 0 * infinity, a CoC of 0 (to the precision a float depth holds the distance).
    EXPECT_LT(std::abs(out.texel(1, 0, 0)), 1e-3f);
    // Beyond far counts as far; below 0 as the near plane.
    EXPECT_EQ(out.texel(2, 0, 0), out.texel(0, 0, 0));
    EXPECT_EQ(out.texel(3, 0, 0), out.texel(0, 0, 0));
    EXPECT_EQ(out.texel(4, 0, 0), out.texel(5, 0, 0));
    EXPECT_NEAR(out.texel(5, 0, 0), signedCocPixels(model, 0.5), 1e-3);
}

TEST_F(DepthOfFieldOnGl, SliderExtremesStayFiniteAndClamped) {
    // What the overlay's sliders reach and the scene loader refuses: the focus at and inside the focal
    // length, at 0 and behind the camera; f-number 0; fields of view near 0 and near 180 deg.
    std::vector<ThinLensInput> inputs;
    for (float focus : {0.0311769f, 0.02f, 0.0f, -1.0f}) {
        ThinLensInput in = chapterCamera(CocConvention::corrected, 32.0f);
        in.lens.focusDistanceM = focus;
        inputs.push_back(in);
        in.convention = CocConvention::chapter;
        inputs.push_back(in);
    }
    ThinLensInput n0 = chapterCamera(CocConvention::corrected, 32.0f);
    n0.lens.fNumber = 0.0f;
    inputs.push_back(n0);
    for (double fov : {0.01, 179.99}) {
        ThinLensInput in = chapterCamera(CocConvention::corrected, 32.0f);
        in.lens.focalLengthMm = float(18.0 / std::tan(fov * M_PI / 360.0));
        inputs.push_back(in);
    }
    for (const ThinLensInput& in : inputs) {
        ThinLensModel model = thinLensModel(in);
        FloatImage out = coc(16, 1, model, [](int x, int) { return float(x) / 15.0f; });
        ASSERT_FALSE(out.empty()) << lastError;
        for (int x = 0; x < 16; ++x) {
            float c = out.texel(x, 0, 0);
            ASSERT_TRUE(std::isfinite(c)) << in.lens.focusDistanceM << " " << x;
            EXPECT_LE(std::abs(c), 32.0f);
            EXPECT_NEAR(c, signedCocPixelsFromDepth(model, float(x) / 15.0f),
                        1e-3 * std::max(1.0f, std::abs(c)));
        }
    }
}

TEST_F(DepthOfFieldOnGl, HugeCocIsClampedAndNeverWrapsAround) {
    // Red, green and blue thirds, everything at the near plane with a CoC far beyond the clamp (20 px
    // of radius here). From the left column the blur reaches 20 px to the right, never the blue third;
    // a tap wrapped around from beyond the left edge would land in it. The same for the right column
    // and red. Taps off the screen must read its edge.
    const int w = 63, h = 63;
    FloatImage split = makeImage(w, h, [](int x, int) {
        if (x < 21) return std::array<float, 4>{1, 0, 0, 1};
        return x < 42 ? std::array<float, 4>{0, 1, 0, 1} : std::array<float, 4>{0, 0, 1, 1};
    });
    ThinLensInput in = chapterCamera(CocConvention::chapter, 20.0f);
    in.lens.focusDistanceM = 300.0f;
    DofLensUniforms lens = dofLensUniforms(thinLensModel(in));
    ASSERT_GT(std::abs(signedCocPixelsUnclamped(thinLensModel(in), 0.5)), 40.0);  // twice the clamp
    auto check = [&](const FloatImage& out, const char* what) {
        ASSERT_FALSE(out.empty()) << lastError;
        ASSERT_TRUE(allFinite(out)) << what;
        // (The gathered texture is half the size at half resolution.)
        for (int y = 0; y < out.height; ++y) {
            EXPECT_EQ(out.texel(0, y, 2), 0.0f) << what << " y " << y;
            EXPECT_EQ(out.texel(out.width - 1, y, 0), 0.0f) << what << " y " << y;
        }
    };
    check(run(
              w, h, split, [](int, int) { return 0.0f; },
              [&](FrameGraph& g, TextureHandle c, TextureHandle d) {
                  return effect.declareChapter(g, c, effect.declareCoc(g, d, lens).output, lens).output;
              }),
          "chapter");
    for (bool half : {false, true}) {
        check(run(
                  w, h, split, [](int, int) { return 0.0f; },
                  [&](FrameGraph& g, TextureHandle c, TextureHandle d) {
                      TextureHandle coc = effect.declareCoc(g, d, lens).output;
                      return effect.declareGather(g, c, coc, lens, {71, half, true, 0.0f}).gathered;
                  }),
              half ? "gather, half" : "gather, full");
    }
}

TEST_F(DepthOfFieldOnGl, GatherKeepsAUniformImageAtEverySize) {
    // Any weighted average of one colour is that colour: at 1x1, 63x63 and odd half sizes, for every
    // kernel, resolution and field setting, with CoCs from near to far across the picture.
    ThinLensInput in = chapterCamera(CocConvention::corrected, 24.0f);
    in.lens.focusDistanceM = 3.0f;
    DofLensUniforms lens = dofLensUniforms(thinLensModel(in));
    const std::array<float, 4> grey{0.25f, 2.5f, 0.75f, 1.0f};
    for (auto [w, h] : {std::pair{1, 1}, std::pair{63, 63}, std::pair{7, 5}, std::pair{33, 17}}) {
        // A copy to capture: C++20 lets a lambda capture a structured binding (P1091), but clang 14,
        // the sanitizer build's compiler, does not implement it yet.
        const int width = w;
        for (int taps : {16, 22, 43, 71}) {
            for (bool half : {false, true}) {
                for (bool separate : {false, true}) {
                    FloatImage out = run(
                        w, h, uniformColour(w, h, grey),
                        [width](int x, int) { return float(x) / float(std::max(width - 1, 1)); },
                        [&](FrameGraph& g, TextureHandle c, TextureHandle d) {
                            TextureHandle coc = effect.declareCoc(g, d, lens).output;
                            return effect.declareGather(g, c, coc, lens, {taps, half, separate, 1.0f}).result;
                        });
                    ASSERT_FALSE(out.empty()) << lastError;
                    float worst = 0;
                    for (int y = 0; y < h; ++y)
                        for (int x = 0; x < w; ++x)
                            for (int ch = 0; ch < 3; ++ch)
                                worst =
                                    std::max(worst, std::abs(out.texel(x, y, ch) - grey[std::size_t(ch)]) /
                                                        grey[std::size_t(ch)]);
                    EXPECT_LE(worst, 2e-3f)
                        << w << "x" << h << " taps " << taps << " half " << half << " separate " << separate;
                }
            }
        }
    }
}

TEST_F(DepthOfFieldOnGl, BlurredForegroundSpreadsOverASharpBackgroundOnlyWithSeparateFields) {
    // Left: a near red object far out of focus; right: a blue background exactly at the focus.
    const int w = 64, h = 8;
    ThinLensInput in = chapterCamera(CocConvention::corrected, 32.0f);
    in.lens.focusDistanceM = 20.0f;
    DofLensUniforms lens = dofLensUniforms(thinLensModel(in));
    const float nearDepth = float(windowDepth(0.6, 0.5, 500.0));
    const float focusDepth = float(windowDepth(20.0, 0.5, 500.0));
    FloatImage split = makeImage(w, h, [](int x, int) {
        return x < 32 ? std::array<float, 4>{1, 0, 0, 1} : std::array<float, 4>{0, 0, 1, 1};
    });
    auto redAt = [&](bool separate, int x) {
        FloatImage out = run(
            w, h, split, [&](int px, int) { return px < 32 ? nearDepth : focusDepth; },
            [&](FrameGraph& g, TextureHandle c, TextureHandle d) {
                TextureHandle coc = effect.declareCoc(g, d, lens).output;
                return effect.declareGather(g, c, coc, lens, {43, false, separate, 0.0f}).result;
            });
        EXPECT_FALSE(out.empty()) << lastError;
        return out.empty() ? -1.0f : out.texel(x, h / 2, 0);
    };
    EXPECT_GT(redAt(true, 34), 0.1f);   // the foreground's blur reaches over the background
    EXPECT_EQ(redAt(false, 34), 0.0f);  // one average: the sharp background stays sharp, a hard edge
    EXPECT_EQ(redAt(true, 60), 0.0f);   // but not beyond its own radius (the clamp: 16 px here)
}

TEST(DofReference, JitteredCameraKeepsTheFocusPlaneAndBlursByTheCoc) {
    // A pinhole moved across the aperture sees the focus plane on the same pixels, and a point at
    // another distance moved by the CoC radius the model gives when the pinhole is at the rim.
    Camera camera;
    camera.position = {0, 1.2f, 0};
    camera.target = {0, 1.2f, -15.264f};
    camera.near = 0.5f;
    camera.far = 500.0f;
    ThinLensInput in = chapterCamera(CocConvention::corrected);
    for (CocConvention convention : {CocConvention::corrected, CocConvention::chapter}) {
        in.convention = convention;
        ThinLensModel model = thinLensModel(in);
        camera.fovYDegrees = dofVerticalFovDegrees(in.lens, convention, 1280.0f / 720.0f);
        CameraMatrices base = cameraMatrices(camera, 1280, 720);
        float aperture = referenceApertureRadiusM(float(model.scalePixelsM), float(model.radiusPerDiameter),
                                                  camera.fovYDegrees, 720);
        CameraMatrices rim = jitteredCamera(base, camera.fovYDegrees, camera.near, camera.far,
                                            glm::vec2(aperture, 0.0f), float(model.focusM));
        auto pixelX = [](const CameraMatrices& m, glm::vec3 p) {
            glm::vec4 clip = m.viewProjection * glm::vec4(p, 1.0f);
            return (clip.x / clip.w * 0.5f + 0.5f) * 1280.0f;
        };
        glm::vec3 onFocus(0.7f, 1.5f, -15.264f), near(0.2f, 1.0f, -2.0f);
        EXPECT_NEAR(pixelX(rim, onFocus), pixelX(base, onFocus), 1e-3f);
        double radius = std::abs(signedCocPixels(model, 2.0)) * model.radiusPerDiameter;
        EXPECT_NEAR(std::abs(pixelX(rim, near) - pixelX(base, near)), radius, 2e-3 * radius);
    }
}

TEST_F(DepthOfFieldOnGl, InFocusPicturesComeBackUnchanged) {
    // Everything at the focus distance: the chapter's 13 taps all land on the pixel itself, and the
    // gather's composite keeps the sharp scene. The naive version is sharp where raw depth is 0.935.
    const int w = 33, h = 17;
    FloatImage patterned = makeImage(w, h, [](int x, int y) {
        std::array<float, 4> v{};
        // Multiples of 1/16 below 4: exact in the effect's RGBA16F outputs.
        for (int c = 0; c < 3; ++c)
            v[std::size_t(c)] = std::floor(fx::test::hashedValue(x, y, c) * 64.0f) / 16.0f;
        v[3] = 1.0f;
        return v;
    });
    ThinLensModel model = thinLensModel(chapterCamera(CocConvention::corrected, 32.0f));
    DofLensUniforms lens = dofLensUniforms(model);
    const float focusDepth = float(windowDepth(model.focusM, 0.5, 500.0));
    auto worstChange = [&](const FloatImage& out) {
        float worst = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst, std::abs(out.texel(x, y, c) - patterned.texel(x, y, c)));
        return worst;
    };
    FloatImage chapter = run(
        w, h, patterned, [&](int, int) { return focusDepth; },
        [&](FrameGraph& g, TextureHandle c, TextureHandle d) {
            return effect.declareChapter(g, c, effect.declareCoc(g, d, lens).output, lens).output;
        });
    ASSERT_FALSE(chapter.empty()) << lastError;
    // 13 equal taps summed and divided by 13 may land a float ulp below the value, and llvmpipe's
    // conversion to half floats truncates: one half-float step (2^-9 between 2 and 4) at most.
    EXPECT_LE(worstChange(chapter), 1.0f / 512.0f);
    for (bool half : {false, true}) {
        FloatImage gathered = run(
            w, h, patterned, [&](int, int) { return focusDepth; },
            [&](FrameGraph& g, TextureHandle c, TextureHandle d) {
                TextureHandle coc = effect.declareCoc(g, d, lens).output;
                return effect.declareGather(g, c, coc, lens, {43, half, true, 0.0f}).result;
            });
        ASSERT_FALSE(gathered.empty()) << lastError;
        EXPECT_EQ(worstChange(gathered), 0.0f) << "half " << half;
    }
    FloatImage naive = run(
        w, h, patterned, [](int, int) { return 0.935f; },
        [&](FrameGraph& g, TextureHandle c, TextureHandle d) {
            return effect.declareNaive(g, c, d, {}).output;
        });
    ASSERT_FALSE(naive.empty()) << lastError;
    EXPECT_LE(worstChange(naive), 1.0f / 512.0f);
    // And elsewhere it blurs: raw depth 1 (the sky) scales the disk by 0.0065 of the screen.
    FloatImage naiveSky = run(
        w, h, patterned, [](int, int) { return 1.0f; },
        [&](FrameGraph& g, TextureHandle c, TextureHandle d) {
            return effect.declareNaive(g, c, d, {}).output;
        });
    ASSERT_FALSE(naiveSky.empty()) << lastError;
    EXPECT_GT(worstChange(naiveSky), 0.1f);
}

TEST_F(DepthOfFieldOnGl, ASharpForegroundLeaksIntoABlurredBackgroundOnlyWithTheChaptersTaps) {
    // Hard case 10, the other direction: left a red object at the focus (2 m, sharp), right a blue
    // background at 50 m (a 12 px CoC, radius 6 px). The chapter's taps are scaled by the centre's CoC
    // alone, so background pixels beside the edge gather the sharp red: a red halo in the blur. The
    // gather counts a tap only as far as its own blur reaches (and, with the fields separated, the
    // smaller of its own and the centre's), so the red has nowhere to go, and it stays sharp itself.
    const int w = 64, h = 8;
    ThinLensInput in = chapterCamera(CocConvention::corrected, 32.0f);
    in.lens.focusDistanceM = 2.0f;
    ThinLensModel model = thinLensModel(in);
    ASSERT_GT(signedCocPixels(model, 50.0), 10.0);
    DofLensUniforms lens = dofLensUniforms(model);
    const float focusDepth = float(windowDepth(2.0, 0.5, 500.0));
    const float backgroundDepth = float(windowDepth(50.0, 0.5, 500.0));
    FloatImage split = makeImage(w, h, [](int x, int) {
        return x < 32 ? std::array<float, 4>{1, 0, 0, 1} : std::array<float, 4>{0, 0, 1, 1};
    });
    auto depth = [&](int x, int) { return x < 32 ? focusDepth : backgroundDepth; };
    FloatImage chapter = run(w, h, split, depth, [&](FrameGraph& g, TextureHandle c, TextureHandle d) {
        return effect.declareChapter(g, c, effect.declareCoc(g, d, lens).output, lens).output;
    });
    ASSERT_FALSE(chapter.empty()) << lastError;
    float leak = 0.0f;
    for (int x = 32; x < 38; ++x) leak = std::max(leak, chapter.texel(x, h / 2, 0));
    EXPECT_GT(leak, 0.05f) << "the chapter's taps should carry the sharp red into the blurred background";

    for (bool separate : {true, false}) {
        FloatImage gathered = run(w, h, split, depth, [&](FrameGraph& g, TextureHandle c, TextureHandle d) {
            TextureHandle coc = effect.declareCoc(g, d, lens).output;
            return effect.declareGather(g, c, coc, lens, {43, false, separate, 0.0f}).result;
        });
        ASSERT_FALSE(gathered.empty()) << lastError;
        ASSERT_TRUE(allFinite(gathered));
        for (int x = 32; x < w; ++x)
            EXPECT_LE(gathered.texel(x, h / 2, 0), 1e-3f) << "separate " << separate << ": red at x " << x;
        for (int x = 0; x < 32; ++x) {
            EXPECT_NEAR(gathered.texel(x, h / 2, 0), 1.0f, 1e-3f) << "separate " << separate << ", x " << x;
            EXPECT_LE(gathered.texel(x, h / 2, 2), 1e-3f) << "separate " << separate << ": blue at x " << x;
        }
    }
}

TEST_F(DepthOfFieldOnGl, NearAndFarThatDisagreeWithTheProjectionMoveTheFocus) {
    // Hard case 7: the depth was written by a projection with near 0.5 m and far 500 m, and the CoC
    // pass is told near 0.6 m. Every depth then reads as another distance, and the focus moves: the
    // object at the focus distance (5 m) blurs by 0.82 px at 1280 px wide, and the one the shader
    // reads as 5 m, 4.17 m away, is sharp. The shader's CoC is the CPU's for the same depth read with
    // the wrong planes.
    ThinLensInput in = chapterCamera(CocConvention::corrected);
    in.lens.focusDistanceM = 5.0f;
    const ThinLensModel agreeing = thinLensModel(in);
    in.nearM = 0.6f;
    const ThinLensModel disagreeing = thinLensModel(in);
    const double movedFocus = linearDepthM(windowDepth(5.0, 0.6, 500.0), 0.5, 500.0);
    ASSERT_NEAR(movedFocus, 4.17, 0.01);
    const double distances[] = {2.0, movedFocus, 5.0, 10.0, 50.0};
    std::vector<float> depths;
    for (double d : distances) depths.push_back(float(windowDepth(d, 0.5, 500.0)));
    auto depthAt = [&](int x, int) { return depths[std::size_t(x)]; };
    FloatImage right = coc(5, 1, agreeing, depthAt);
    FloatImage wrong = coc(5, 1, disagreeing, depthAt);
    ASSERT_FALSE(right.empty() || wrong.empty()) << lastError;
    for (int x = 0; x < 5; ++x) {
        const float d = depths[std::size_t(x)];
        EXPECT_NEAR(right.texel(x, 0, 0), signedCocPixelsFromDepth(agreeing, d), 1e-3)
            << distances[x] << " m";
        EXPECT_NEAR(wrong.texel(x, 0, 0), signedCocPixelsFromDepth(disagreeing, d), 1e-3)
            << distances[x] << " m";
    }
    EXPECT_LT(std::abs(right.texel(2, 0, 0)), 1e-3f) << "in focus at 5 m when the planes agree";
    EXPECT_GT(std::abs(right.texel(1, 0, 0)), 0.5f) << "and blurred at " << movedFocus << " m";
    EXPECT_GT(std::abs(wrong.texel(2, 0, 0)), 0.5f) << "with the wrong near plane the object at 5 m blurs";
    EXPECT_LT(std::abs(wrong.texel(1, 0, 0)), 1e-2f) << "and the one at " << movedFocus << " m is sharp";
}

TEST_F(DepthOfFieldOnGl, ALinearlyFilteredDepthGivesASilhouetteACocOfNeitherObject) {
    // Hard case 10's other half, filtered-depth halos: a half-resolution CoC computed from one bilinear
    // tap of the depth (the tap between the 2 x 2 texels it stands for) mixes the depths of a silhouette,
    // and the mixed depth is a distance where neither object is (about 2 m between a foreground at 1 m
    // and a background at 50 m): a ring with a CoC of neither, a halo in the blur. fxlab's CoC pass reads
    // every depth texel with texelFetch, and the same half-resolution pass with a NEAREST sampler reads one
    // of the four: each CoC is one object's.
    const int w = 64, h = 4;
    ThinLensInput in = chapterCamera(CocConvention::corrected, 32.0f);
    in.lens.focusDistanceM = 5.0f;
    const ThinLensModel model = thinLensModel(in);
    const DofLensUniforms lens = dofLensUniforms(model);
    const float nearDepth = float(windowDepth(1.0, 0.5, 500.0));
    const float farDepth = float(windowDepth(50.0, 0.5, 500.0));
    const float nearCoc = float(signedCocPixels(model, 1.0)), farCoc = float(signedCocPixels(model, 50.0));
    ASSERT_LT(nearCoc, -4.0f);
    ASSERT_GT(farCoc, 1.0f);
    // The silhouette between texels 32 and 33: half-resolution texel 16 stands for columns 32 and 33.
    auto depth = [&](int x, int) { return x <= 32 ? nearDepth : farDepth; };

    // A CoC pass at half resolution whose depth comes through `sampler` at the 2 x 2 block's centre.
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("fx_dof_halo_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "filtered_coc.frag")
        << "#version 450 core\n"
           "#include \"effects/dof/coc.glsl\"\n"
           "layout(binding = 0) uniform sampler2D depth;\n"
           "layout(location = 1) in vec2 uv;\n"
           "layout(location = 0) out float coc;\n"
           "void main() { coc = signedCocPixels(texture(depth, uv).r); }\n";
    FullscreenPass filtered((dir / "filtered_coc.frag").string(), "test coc from a filtered depth");
    std::filesystem::remove_all(dir);
    ASSERT_TRUE(programsBuilt());
    auto halfResolutionCoc = [&](GLenum filter) {
        gl::SamplerName sampler = gl::createLinearClampSampler("test depth sampler");
        glSamplerParameteri(sampler.name(), GL_TEXTURE_MIN_FILTER, GLint(filter));
        glSamplerParameteri(sampler.name(), GL_TEXTURE_MAG_FILTER, GLint(filter));
        const FullscreenPass* program = &filtered;
        const GLuint s = sampler.name();
        return run(w, h, uniformColour(w, h, {0, 0, 0, 1}), depth,
                   [&](FrameGraph& g, TextureHandle, TextureHandle d) {
                       Pass& pass =
                           filtered.addPass(g, "test filtered coc", [program, d, lens, s](PassContext& ctx) {
                               glProgramUniform2f(program->program(), glsl::kDofDepthRangeLocation,
                                                  lens.nearM, lens.farM);
                               glProgramUniform4f(program->program(), glsl::kDofLensLocation,
                                                  lens.inverseFocusM, lens.scalePixelsM, lens.maxCocPixels,
                                                  lens.radiusPerDiameter);
                               glBindSampler(0, s);
                               program->draw({ctx.native(d)});
                               glBindSampler(0, 0);
                           });
                       pass.read(d).setTaps(1);
                       return pass.create("test.coc_half",
                                          {TextureSize::outputFraction(1, 2), TextureFormat::R32F, 1},
                                          TextureUsage::ColorAttachment);
                   });
    };
    auto ofOneObject = [&](float c) { return std::abs(c - nearCoc) < 1e-3f || std::abs(c - farCoc) < 1e-3f; };

    FloatImage linear = halfResolutionCoc(GL_LINEAR);
    ASSERT_FALSE(linear.empty()) << lastError;
    ASSERT_EQ(linear.width, w / 2);
    const float halo = linear.texel(16, 1, 0);
    std::printf("near %.3f px, far %.3f px; the silhouette's CoC from a filtered depth %.3f px\n", nearCoc,
                farCoc, halo);
    EXPECT_GT(halo, nearCoc + 1.0f) << "the filtered depth's CoC should belong to neither object";
    EXPECT_LT(halo, farCoc - 0.5f) << "the filtered depth's CoC should belong to neither object";
    EXPECT_TRUE(ofOneObject(linear.texel(15, 1, 0)) && ofOneObject(linear.texel(17, 1, 0)));

    FloatImage nearest = halfResolutionCoc(GL_NEAREST);
    ASSERT_FALSE(nearest.empty()) << lastError;
    for (int x = 0; x < w / 2; ++x) EXPECT_TRUE(ofOneObject(nearest.texel(x, 1, 0))) << "NEAREST, x " << x;
    FloatImage fetched = coc(w, h, model, depth);
    ASSERT_FALSE(fetched.empty()) << lastError;
    for (int x = 0; x < w; ++x)
        EXPECT_NEAR(fetched.texel(x, 1, 0), x <= 32 ? nearCoc : farCoc, 1e-3f) << "texelFetch, x " << x;
}
