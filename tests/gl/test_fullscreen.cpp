// The pieces every post effect shares: the full-screen pass, the one output transform (the chapter's
// gamma test vectors), the split view, and the linear-HDR scene pass's limits.
#include <cmath>

#include "effects/post/colour_matrix.hpp"
#include "effects/post/fullscreen_pass.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "gl_test.hpp"
#include "test_fullscreen_harness.hpp"

using namespace fx;
using fx::test::EffectRunner;
using fx::test::makeImage;

class FullscreenOnGl : public GlTest {};

TEST_F(FullscreenOnGl, OutputTransformEncodesTheChaptersTestVectorsWithTheSrgbCurve) {
    // The chapter's vectors (0.5, 0.2126, 0.7152) through the exact sRGB curve: 188, 127, 220. The
    // chapter's pow(c, 1/2.2) gives 186, 126, 219: close, but darker in the shadows. HDR clips to 255,
    // negative values to 0 (not NaN).
    const std::vector<std::pair<float, int>> vectors{{0.5f, 188}, {0.2126f, 127}, {0.7152f, 220}, {0.0f, 0},
                                                     {1.0f, 255}, {40.0f, 255},   {-3.0f, 0}};
    OutputTransformPass present;
    ASSERT_TRUE(programsBuilt());
    EffectRunner runner(int(vectors.size()), 1);
    FloatImage input = makeImage(int(vectors.size()), 1, [&](int x, int) {
        float v = vectors[std::size_t(x)].first;
        return std::array<float, 4>{v, v, v, 1.0f};
    });
    runner.run(input, TextureFormat::RGBA32F, [&](FrameGraph& g, TextureHandle in) {
        present.declare(g, in);
        return in;
    });
    ASSERT_TRUE(runner.lastError.empty()) << runner.lastError;
    for (std::size_t i = 0; i < vectors.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(runner.presented.texel(int(i), 0, c), vectors[i].second)
                << "linear " << vectors[i].first;
        }
    }
}

TEST_F(FullscreenOnGl, SepiaWhiteClipsInRed) {
    // White through the chapter's sepia is linear (1.175, 0.948, 0.670): on screen (255, 249, 214) with
    // the sRGB curve (the chapter's 1/2.2 power gives 213 for blue). Red is above 1 and clips.
    ColourMatrixPass grading;
    grading.setTransform(ColourTransform::sepia());
    OutputTransformPass present;
    EffectRunner runner(1, 1);
    FloatImage white = makeImage(1, 1, [](int, int) { return std::array<float, 4>{1, 1, 1, 1}; });
    runner.run(white, TextureFormat::RGBA16F, [&](FrameGraph& g, TextureHandle in) {
        DeclaredPass graded = grading.declare(g, in);
        present.declare(g, graded.output);
        return graded.output;
    });
    ASSERT_TRUE(runner.lastError.empty()) << runner.lastError;
    EXPECT_EQ(runner.presented.texel(0, 0, 0), 255);
    EXPECT_EQ(runner.presented.texel(0, 0, 1), 249);
    EXPECT_EQ(runner.presented.texel(0, 0, 2), 214);
}

TEST_F(FullscreenOnGl, SplitViewShowsBeforeLeftOfTheDividerAndAfterRightOfIt) {
    const int width = 20;
    ColourMatrixPass grading;
    grading.setTransform(ColourTransform::invert());
    OutputTransformPass present;
    EffectRunner runner(width, 2);
    FloatImage black = makeImage(width, 2, [](int, int) { return std::array<float, 4>{0, 0, 0, 1}; });
    for (float divider : {0.0f, 0.3f, 1.0f}) {
        runner.run(black, TextureFormat::RGBA16F, [&](FrameGraph& g, TextureHandle in) {
            DeclaredPass graded = grading.declare(g, in);
            present.declare(g, graded.output, SplitView{in, divider});
            return graded.output;
        });
        ASSERT_TRUE(runner.lastError.empty()) << runner.lastError;
        int line = splitDividerPixel(divider, width);
        for (int x = 0; x < width; ++x) {
            int expected = x < line ? 0 : 255;  // before: black; after: inverted, white
            if (x == line) expected = 255;      // the divider line: white, with black left of it
            if (x == line - 1) expected = 0;
            EXPECT_EQ(runner.presented.texel(x, 1, 0), expected) << "divider " << divider << ", column " << x;
        }
    }
    EXPECT_EQ(splitDividerPixel(0.3f, 20), 6);
    EXPECT_EQ(splitDividerPixel(-2.0f, 20), 0);
    EXPECT_EQ(splitDividerPixel(std::nanf(""), 20), 0);
    EXPECT_EQ(splitDividerPixel(7.0f, 20), 20);
}

TEST_F(FullscreenOnGl, FullscreenStateSetsEverythingAPostPassDependsOn) {
    PassState s = FullscreenPass::state();
    EXPECT_EQ(s.depthTest, false);
    EXPECT_EQ(s.depthWrite, false);
    EXPECT_EQ(s.blend, false);
    EXPECT_EQ(s.faceCulling, false);
    EXPECT_TRUE(s.colorMask.has_value());
}

TEST_F(FullscreenOnGl, AnEffectWhoseProgramFailedIsSwitchedOffWithTheReason) {
    expectBrokenPrograms();
    FullscreenPass missing("effects/no_such_shader.frag", "missing");
    EXPECT_FALSE(missing.reloadable().usable());
    EXPECT_FALSE(missing.reloadable().error().empty());
    // A pass that draws with it says so in the frame report instead of drawing with program 0.
    EffectRunner runner(4, 4);
    FloatImage grey = makeImage(4, 4, [](int, int) { return std::array<float, 4>{0.5f, 0.5f, 0.5f, 1}; });
    runner.run(grey, TextureFormat::RGBA16F, [&](FrameGraph& g, TextureHandle in) {
        const FullscreenPass* pass = &missing;
        missing
            .addPass(g, "copy with a missing shader",
                     [pass, in](PassContext& ctx) { pass->draw({ctx.native(in)}); })
            .read(in)
            .writeColor(g.output());
        return in;
    });
    const PassRecord* record = runner.report.findPass("copy with a missing shader");
    ASSERT_NE(record, nullptr);
    EXPECT_FALSE(record->executed);
    EXPECT_NE(record->reason.find("the missing program did not build"), std::string::npos) << record->reason;
}

TEST_F(FullscreenOnGl, TheHdrSceneIsWrittenFiniteAndWithinItsLimit) {
    // An emitter of 1e8 (far above a half float's 65504) and a sky of 1e5: the scene pass must write
    // finite values no larger than kSceneHdrMax, or one infinite texel would spread through every blur.
    Scene scene;
    scene.background = glm::vec3(1e5f, 0.5f, 0.0f);
    scene.camera.position = {0, 0, 5};
    scene.camera.target = {0, 0, 0};
    SceneObject ball;
    ball.name = "too bright";
    ball.primitive = Primitive{PrimitiveShape::sphere, {}, {}, 1.5f, 1.0f};
    ball.material.emissive = glm::vec3(1e4f, 2.0f, 0.0f);
    ball.material.emissiveStrength = 1e4f;
    scene.objects.push_back(ball);
    SceneMeshes meshes(scene);
    HdrScenePass scenePass;
    ASSERT_TRUE(programsBuilt());
    EffectRunner runner(16, 16);
    FloatImage unused = makeImage(16, 16, [](int, int) { return std::array<float, 4>{0, 0, 0, 1}; });
    FloatImage hdr = runner.run(unused, TextureFormat::RGBA16F, [&](FrameGraph& g, TextureHandle) {
        return scenePass.declare(g, World(scene, meshes, 0.0)).color;
    });
    ASSERT_FALSE(hdr.empty()) << runner.lastError;
    EXPECT_EQ(hdr.texel(8, 8, 0), kSceneHdrMax) << "the ball, clamped";
    EXPECT_EQ(hdr.texel(0, 0, 0), kSceneHdrMax) << "the sky, clamped";
    EXPECT_NEAR(hdr.texel(0, 0, 1), 0.5f, 1e-3f) << "the sky's green is untouched";
    for (float v : hdr.texels) {
        ASSERT_TRUE(std::isfinite(v));
        ASSERT_GE(v, 0.0f);
        ASSERT_LE(v, kSceneHdrMax);
    }
}
