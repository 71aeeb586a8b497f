// Deferred shading's targets (Deferred rendering chapter, lesson 10): framebuffers that would lose
// writes silently (a draw buffer naming a missing attachment, a fragment output without one, an
// incomplete MRT framebuffer), what the render-to-texture framebuffers say is attached, the slides'
// sharpening in float and in eight bits, and raw RGBA8 normals. Read back as floats.
#include "test_deferred_harness.hpp"

using namespace fx;
using namespace fx::test;

TEST_F(DeferredHardCases, ADrawBufferNamingAMissingAttachmentIsANamedError) {
    gl::Texture color = gl::Texture::create2D(TextureFormat::RGBA8, 8, 8, 1, "test.mrt0");
    gl::Framebuffer fbo("test mrt");
    fbo.attachColor(0, color);
    const GLenum list[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(fbo.name(), 2, list);
    Status status = fbo.checkComplete();
    ASSERT_FALSE(status);
    EXPECT_NE(status.error().find("draw buffer 1 of test mrt names GL_COLOR_ATTACHMENT1, which has no image"),
              std::string::npos)
        << status.error();
    fbo.setDrawBuffers(1);
    EXPECT_TRUE(fbo.checkComplete());
}

TEST_F(DeferredHardCases, AFragmentOutputWithoutAnAttachmentIsANamedError) {
    // The lecture's three-output shader against a framebuffer with two targets: output 2 is lost.
    gl::ReloadableProgram mrt({"effects/deferred/lit_scene.vert",
                               "effects/deferred/phong.frag",
                               {},
                               "#define THREE_TARGETS 1",
                               "test mrt program"});
    ASSERT_TRUE(programsBuilt());
    gl::Texture a = gl::Texture::create2D(TextureFormat::RGBA8, 8, 8, 1, "test.a");
    gl::Texture b = gl::Texture::create2D(TextureFormat::RGBA8, 8, 8, 1, "test.b");
    gl::Framebuffer fbo("two targets");
    fbo.attachColor(0, a);
    fbo.attachColor(1, b);
    fbo.setDrawBuffers(2);
    ASSERT_TRUE(fbo.checkComplete());
    Status status = gl::checkProgramOutputs(mrt.name(), fbo.name(), fbo.label());
    ASSERT_FALSE(status);
    EXPECT_NE(status.error().find("output 'ambient' (location 2) has no entry in the draw-buffer list of two "
                                  "targets"),
              std::string::npos)
        << status.error();
    // What the MRT and G-buffer passes call when they draw: the same answer, logged by pass name.
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.name());
    EXPECT_FALSE(checkOutputsOnce(mrt.name(), "test pass"));
    EXPECT_FALSE(checkOutputsOnce(mrt.name(), "test pass"));  // remembered
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::Texture c = gl::Texture::create2D(TextureFormat::RGBA8, 8, 8, 1, "test.c");
    fbo.attachColor(2, c);
    fbo.setDrawBuffers(3);
    EXPECT_TRUE(gl::checkProgramOutputs(mrt.name(), fbo.name(), fbo.label()));
}

TEST_F(DeferredHardCases, AnIncompleteMrtFramebufferIsANamedError) {
    gl::Texture color = gl::Texture::create2D(TextureFormat::RGBA8, 8, 8, 1, "test.color");
    gl::Texture depth = gl::Texture::create2D(TextureFormat::Depth32F, 8, 8, 1, "test.depth");
    gl::Framebuffer fbo("mrt with a depth texture as colour 1");
    fbo.attachColor(0, color);
    fbo.attachColor(1, depth);  // a depth format cannot be a colour attachment
    fbo.setDrawBuffers(2);
    Status status = fbo.checkComplete();
    ASSERT_FALSE(status);
    EXPECT_EQ(status.error(), "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT on mrt with a depth texture as colour 1");
}

TEST_F(DeferredHardCases, TheRenderToTextureFramebuffersSayWhatIsAttached) {
    RenderToTexture rtt;
    EXPECT_EQ(rtt.attachmentsText(RttDepth::renderbuffer),
              "colour 0: texture rtt.color RGBA8 512x512; depth: renderbuffer GL_DEPTH_COMPONENT24 512x512");
    EXPECT_EQ(rtt.attachmentsText(RttDepth::texture),
              "colour 0: texture rtt.color RGBA8 512x512; depth: texture rtt.depth Depth32F 512x512");
}

namespace {

// Imports an RGBA float image as a texture of `format` named `name`.
struct ImportedImage {
    gl::Texture texture;
    TextureHandle import(FrameGraph& graph, const char* name) const {
        return graph.importTexture(name, texture.spec(), texture.name());
    }
};
ImportedImage upload(const FloatImage& image, TextureFormat format, const char* label) {
    ImportedImage out{gl::Texture::create2D(format, image.width, image.height, 1, label)};
    glTextureSubImage2D(out.texture.name(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_FLOAT,
                        image.texels.data());
    return out;
}

}  // namespace

// The slides' sharpening kernel on the diffuse term: one lit texel on black gives 5 at the texel and -1
// at its four neighbours; the float target keeps both, the RGBA8 target clips them to 1 and 0. And the
// sky is added once where no surface is (not three times, as a glClear of every target would).
TEST_F(DeferredHardCases, SharpeningReachesItsRangeInFloatAndClipsInEightBits) {
    const int w = 5, h = 5;
    FloatImage diffuse = test::makeImage(w, h, [](int x, int y) {
        float v = (x == 2 && y == 2) ? 1.0f : 0.0f;
        return std::array<float, 4>{v, v, v, 0.0f};
    });
    FloatImage zero = test::makeImage(w, h, [](int, int) { return std::array<float, 4>{0, 0, 0, 0}; });
    // Ambient alpha 1 (a surface) everywhere but the corner (0, 0): the sky shows there.
    FloatImage ambient = test::makeImage(w, h, [](int x, int y) {
        return std::array<float, 4>{0, 0, 0, (x == 0 && y == 0) ? 0.0f : 1.0f};
    });
    ImportedImage d = upload(diffuse, TextureFormat::RGBA8, "test.diffuse");
    ImportedImage s = upload(zero, TextureFormat::RGBA8, "test.specular");
    ImportedImage a = upload(ambient, TextureFormat::RGBA8, "test.ambient");
    Scene scene;
    scene.background = glm::vec3(0.2f, 0.4f, 0.6f);
    LectureMrt mrt;
    ASSERT_TRUE(programsBuilt());
    GlFrameRunner runner({w, h});
    SharpenTargets targets;
    auto declare = [&](FrameGraph& graph) {
        MrtTargets t{d.import(graph, "mrt.diffuse"),
                     s.import(graph, "mrt.specular"),
                     a.import(graph, "mrt.ambient"),
                     {}};
        targets = mrt.declareSharpen(graph, scene, t);
        return targets.kept;
    };
    FloatImage kept = runner.frameAndRead(declare);
    FloatImage clipped = runner.frameAndRead([&](FrameGraph& graph) {
        declare(graph);
        return targets.clipped;
    });
    ASSERT_FALSE(kept.empty());
    ASSERT_FALSE(clipped.empty());
    EXPECT_EQ(kept.texel(2, 2, 0), 5.0f);
    EXPECT_EQ(clipped.texel(2, 2, 0), 1.0f);
    for (auto [x, y] : {std::pair{1, 2}, {3, 2}, {2, 1}, {2, 3}}) {
        EXPECT_EQ(kept.texel(x, y, 0), -1.0f) << x << "," << y;
        EXPECT_EQ(clipped.texel(x, y, 0), 0.0f) << x << "," << y;
    }
    EXPECT_EQ(kept.texel(4, 4, 0), 0.0f);  // flat: the kernel sums to 1
    // The sky once, in the corner only (RGBA16F rounds 0.2, 0.4, 0.6 to its nearest values).
    EXPECT_NEAR(kept.texel(0, 0, 0), 0.2f, 1e-3f);
    EXPECT_NEAR(kept.texel(0, 0, 2), 0.6f, 1e-3f);
    EXPECT_EQ(kept.texel(4, 0, 2), 0.0f);
}

// Normals in RGBA8 without the remap lose their negative half: on the lesson's scene the fat layout
// stores negative components where the rgba8Raw layout stores 0, and nothing below 0.
TEST_F(DeferredHardCases, RawRgba8NormalsLoseTheirNegativeHalf) {
    auto scene = loadShippedScene();
    ASSERT_TRUE(scene.ok()) << scene.error();
    SceneMeshes meshes(*scene);
    GBufferPass gbuffer;
    const Size2D size{96, 54};
    GlFrameRunner runner(size);
    auto normals = [&](GBufferLayout layout) {
        return runner.frameAndRead([&](FrameGraph& graph) {
            return gbuffer.declare(graph, World(*scene, meshes, 0.0), {layout, false, glm::vec3(0)}).normal;
        });
    };
    FloatImage fat = normals(GBufferLayout::fat), raw = normals(GBufferLayout::rgba8Raw);
    ASSERT_FALSE(fat.empty());
    ASSERT_FALSE(raw.empty());
    int negative = 0, clippedToZero = 0;
    for (int y = 0; y < size.height; ++y)
        for (int x = 0; x < size.width; ++x)
            for (int c = 0; c < 3; ++c) {
                EXPECT_GE(raw.texel(x, y, c), 0.0f);
                if (fat.texel(x, y, c) < -0.1f) {
                    ++negative;
                    clippedToZero += raw.texel(x, y, c) == 0.0f;
                }
            }
    EXPECT_GT(negative, 50);  // the objects' sides facing -X and -Z (toward the camera: +Z)
    EXPECT_EQ(clippedToZero, negative);
}

// The lecture's forward picture (render to texture: the Phong sum in one RGBA8 target) against its
// deferred one (the three terms in three RGBA8 targets, added by the composite into RGBA16F), on the
// lesson's scene at 512 x 512, the render-to-texture target's size: the same pixels, so they differ
// only by rounding. Each stored term rounds by at most 0.5/255, so the deferred sum is within
// 3 x 0.5/255 of the exact one; the forward picture rounds once more (0.5/255) and the half float of
// the sum by at most 2^-11 of it. Pixels where a term or the sum reaches 1 are clipped differently by
// the two (one clip of the sum, one of each term) and are left out.
TEST_F(DeferredHardCases, ForwardAndDeferredAgreeToEightBitQuantisation) {
    auto scene = loadShippedScene();
    ASSERT_TRUE(scene.ok()) << scene.error();
    SceneMeshes meshes(*scene);
    RenderToTexture rtt;
    LectureMrt mrt;
    ASSERT_TRUE(programsBuilt());
    const Size2D size{512, 512};
    GlFrameRunner runner(size);
    FloatImage forward = runner.frameAndRead([&](FrameGraph& graph) {
        return rtt.declare(graph, World(*scene, meshes, 0.0), RttDepth::renderbuffer);
    });
    MrtTargets targets;
    auto declareTerms = [&](FrameGraph& graph) {
        targets = mrt.declare(graph, World(*scene, meshes, 0.0), MrtOrder::fixed, nullptr);
    };
    FloatImage sum = runner.frameAndRead([&](FrameGraph& graph) {
        declareTerms(graph);
        return mrt.declareComposite(graph, *scene, targets);
    });
    FloatImage terms[3];
    for (int i = 0; i < 3; ++i)
        terms[i] = runner.frameAndRead([&](FrameGraph& graph) {
            declareTerms(graph);
            return i == 0 ? targets.diffuse : i == 1 ? targets.specular : targets.ambient;
        });
    ASSERT_FALSE(forward.empty());
    ASSERT_FALSE(sum.empty());
    ASSERT_EQ(forward.width, sum.width);
    const float bound = 3 * 0.5f / 255;
    float worst = 0;
    double total = 0;
    int compared = 0, lit = 0;
    for (int y = 0; y < size.height; ++y)
        for (int x = 0; x < size.width; ++x)
            for (int c = 0; c < 3; ++c) {
                float f = forward.texel(x, y, c), s = sum.texel(x, y, c);
                bool clipped = f >= 1.0f || s >= 1.0f;
                for (const FloatImage& t : terms) clipped = clipped || t.texel(x, y, c) >= 1.0f;
                if (clipped) continue;
                float d = s - f;
                ASSERT_LE(std::abs(d), bound + 0.5f / 255 + s / 2048 + 1e-6f)
                    << "pixel " << x << "," << y << " channel " << c << ": forward " << f << ", deferred "
                    << s;
                worst = std::max(worst, std::abs(d));
                total += d;
                ++compared;
                lit += terms[0].texel(x, y, c) > 0.0f && terms[1].texel(x, y, c) > 0.0f;
            }
    std::printf(
        "forward against deferred: %d channels compared, largest difference %.3f/255, mean %.4f/255\n",
        compared, worst * 255, total / std::max(compared, 1) * 255);
    EXPECT_GT(compared, size.width * size.height * 2);  // most of the picture takes part
    EXPECT_GT(lit, 1000);                               // with diffuse and specular light both there
    EXPECT_GT(worst, 0.0f);                             // the roundings do differ...
    EXPECT_LT(std::abs(total / compared), 0.5 / 255);   // ... but not on average
}
