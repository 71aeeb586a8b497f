// Deferred shading's hard cases (Deferred rendering chapter, lesson 10), read back as floats: the
// lighting pass on a G-buffer the test writes texel by texel (zero-length, back-facing and fold
// normals, a light of radius 0, a light inside the surface, 1024 lights on one pixel) against a CPU
// evaluation of the same formula; the octahedral code; the position error of the fat and compact
// layouts 1,000 and 10,000 m from the origin; and framebuffers that would lose writes silently.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>

#include "base/log.hpp"
#include "base/paths.hpp"
#include "effects/deferred/deferred_lighting.hpp"
#include "effects/deferred/gbuffer_pass.hpp"
#include "effects/deferred/lecture_mrt.hpp"
#include "effects/deferred/output_check.hpp"
#include "effects/deferred/point_light_buffer.hpp"
#include "effects/deferred/render_to_texture.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "gl/framebuffer.hpp"
#include "gl/program.hpp"
#include "gl/readback.hpp"
#include "gl/texture.hpp"
#include "gl_test.hpp"
#include "render/frame_graph.hpp"
#include "render/texture_pool.hpp"
#include "render_gl/gl_pass_executor.hpp"
#include "render_gl/gl_texture_allocator.hpp"
#include "render_gl/pass_timer.hpp"
#include "scene/scene_loader.hpp"
#include "test_fullscreen_harness.hpp"

using namespace fx;

namespace {

constexpr int kW = 6, kH = 1;
// Exact in RGBA8 (153, 102 and 51 over 255), so the stored albedo is the one the CPU side uses.
const glm::vec3 kAlbedo(0.6f, 0.4f, 0.2f);

bool finite(const FloatImage& image) {
    return std::all_of(image.texels.begin(), image.texels.end(), [](float v) { return std::isfinite(v); });
}

// Runs frame-graph passes on the GL executor, as a lesson does.
struct GraphRunner {
    GlTextureAllocator allocator;
    TexturePool pool{allocator};
    PassTimer timer{TimingMode::Off, ""};
    GlPassExecutor executor{timer, {0, true}};
    gl::Texture output;
    gl::Framebuffer outputFbo{"test.output"};

    GraphRunner(int w, int h) : output(gl::Texture::create2D(TextureFormat::RGBA8, w, h, 1, "test.output")) {
        outputFbo.attachColor(0, output);
        outputFbo.setDrawBuffers(1);
        executor.setPresentFramebuffer(outputFbo.name());
    }

    template <class Declare>
    FloatImage run(Size2D size, Declare declare) {
        FrameGraph graph(OutputTarget{size, "output", TextureFormat::RGBA8, 0});
        TextureHandle result = declare(graph);
        graph.capture(result);
        FloatImage out;
        Status status = graph.execute(pool, executor);
        EXPECT_TRUE(status) << (status ? "" : status.error());
        if (status) out = gl::readTexture(graph.texture(result).native, graph.texture(result).spec, 0);
        graph.releaseTextures();
        pool.endFrame();
        test::EffectRunner::restoreInitialState();
        return out;
    }
};

// A scene with no light but the point lights the test gives: a black sun (setFrameUniforms would
// otherwise use a default white one), no ambient, the default camera.
Scene darkScene() {
    Scene scene;
    Light sun;
    sun.type = LightType::directional;
    sun.intensity = 0.0f;
    scene.lights.push_back(sun);
    scene.ambient = glm::vec3(0.0f);
    scene.background = glm::vec3(0.0f);
    return scene;
}

// The world position the compact layout rebuilds for pixel (x, 0) at depth 0.5.
glm::vec3 worldAt(const Scene& scene, int x, float depth = 0.5f) {
    CameraMatrices c = cameraMatrices(scene.camera, kW, kH);
    glm::vec4 ndc((float(x) + 0.5f) / kW * 2 - 1, 0.5f / kH * 2 - 1, depth * 2 - 1, 1);
    glm::vec4 h = glm::inverse(c.viewProjection) * ndc;
    return glm::vec3(h) / h.w;
}

// The lighting pass's point-light formula on the CPU (point_lights.glsl), for one light.
glm::vec3 expectedLight(const Scene& scene, glm::vec3 p, glm::vec3 n, const GpuPointLight& light) {
    glm::vec3 toLight = glm::vec3(light.positionRadius) - p;
    float d = glm::length(toLight), r = light.positionRadius.w;
    if (!(r > 0) || d >= r) return glm::vec3(0);
    float w = 1 - (d / r) * (d / r), att = w * w;
    glm::vec3 l = d > 1e-4f ? toLight / d : n;
    float lambert = std::max(glm::dot(n, l), 0.0f);
    if (lambert <= 0) return glm::vec3(0);
    glm::vec3 v = glm::normalize(scene.camera.position - p);
    glm::vec3 h = glm::normalize(l + v);
    return att * glm::vec3(light.color) *
           (kAlbedo * lambert + 0.3f * std::pow(std::max(glm::dot(n, h), 0.0f), 40.0f));
}

class DeferredHardCases : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        lighting = DeferredLighting::create();
        lights = PointLightBuffer::create();
    }

    // The lesson's own scene, with its assets resolved from res/.
    static Result<Scene> loadShippedScene() {
        SceneLoadOptions options;
        options.assetRoot = resourceDir();
        return loadScene(resourceDir() / "scenes/10_deferred_shading.json", options);
    }

    // Lights a compact G-buffer of kW x 1 pixels, all at depth 0.5 with albedo kAlbedo, whose normals
    // are the octahedral codes `codes`, with `pointLights`; returns deferred.color.
    FloatImage light(const Scene& scene, const std::vector<glm::vec2>& codes,
                     const std::vector<GpuPointLight>& pointLights) {
        gl::Texture albedo = gl::Texture::create2D(TextureFormat::RGBA8, kW, kH, 1, "test.albedo");
        gl::Texture normal = gl::Texture::create2D(TextureFormat::RG16F, kW, kH, 1, "test.normal");
        gl::Texture depth = gl::Texture::create2D(TextureFormat::Depth32F, kW, kH, 1, "test.depth");
        std::vector<float> a, nrm, d;
        for (int x = 0; x < kW; ++x) {
            a.insert(a.end(), {kAlbedo.r, kAlbedo.g, kAlbedo.b, 1.0f});
            nrm.insert(nrm.end(), {codes[std::size_t(x)].x, codes[std::size_t(x)].y});
            d.push_back(0.5f);
        }
        glTextureSubImage2D(albedo.name(), 0, 0, 0, kW, kH, GL_RGBA, GL_FLOAT, a.data());
        glTextureSubImage2D(normal.name(), 0, 0, 0, kW, kH, GL_RG, GL_FLOAT, nrm.data());
        glTextureSubImage2D(depth.name(), 0, 0, 0, kW, kH, GL_DEPTH_COMPONENT, GL_FLOAT, d.data());
        lights.upload(pointLights);
        GraphRunner runner(kW, kH);
        return runner.run({kW, kH}, [&](FrameGraph& graph) {
            GBufferTargets g;
            g.layout = GBufferLayout::compact;
            g.albedo = graph.importTexture("gbuffer.albedo", albedo.spec(), albedo.name());
            g.normal = graph.importTexture("gbuffer.normal", normal.spec(), normal.name());
            g.depth = graph.importTexture("gbuffer.depth", depth.spec(), depth.name());
            return lighting.declare(graph, scene, g, lights, DeclaredShadowMap{}, std::nullopt);
        });
    }

    DeferredLighting lighting;
    PointLightBuffer lights;
};

glm::vec3 texel(const FloatImage& image, int x) {
    return {image.texel(x, 0, 0), image.texel(x, 0, 1), image.texel(x, 0, 2)};
}

void expectNear(glm::vec3 got, glm::vec3 want, const char* what) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(got[c], want[c], 2e-3f * std::max(1.0f, std::abs(want[c]))) << what << " channel " << c;
}

}  // namespace

TEST(OctahedralCode, RoundTripsEveryDirectionIncludingTheFoldAndTheSouthPole) {
    std::vector<glm::vec3> normals = {{0, 0, 1},        {0, 0, -1},       {1, 0, 0},       {-1, 0, 0},
                                      {0, 1, 0},        {0, -1, 0},       {0.6f, 0.8f, 0}, {-0.6f, 0.8f, 0},
                                      {0.6f, -0.8f, 0}, {-0.8f, -0.6f, 0}};
    for (int i = 0; i < 200; ++i) {  // and a spread of directions from an integer hash
        glm::vec3 v(test::hashedValue(i, 1, 0) * 2 - 1, test::hashedValue(i, 2, 0) * 2 - 1,
                    test::hashedValue(i, 3, 0) * 2 - 1);
        if (glm::length(v) > 1e-3f) normals.push_back(glm::normalize(v));
    }
    for (glm::vec3 n : normals) {
        glm::vec2 e = octahedralEncode(n);
        EXPECT_LE(std::max(std::abs(e.x), std::abs(e.y)), 1.0f + 1e-6f);  // in the square
        if (n.z >= 0.0f) {  // the upper half: inside the diamond
            EXPECT_LE(std::abs(e.x) + std::abs(e.y), 1.0f + 1e-6f);
        }
        glm::vec3 back = octahedralDecode(e);
        EXPECT_LT(glm::length(back - n), 1e-5f) << n.x << " " << n.y << " " << n.z;
        if (n.z == 0.0f) {  // on the fold both halves agree: |x| + |y| = 1 exactly
            EXPECT_NEAR(std::abs(e.x) + std::abs(e.y), 1.0f, 1e-6f);
        }
    }
    // No direction: a code outside the square, decoding to the zero vector.
    EXPECT_EQ(octahedralEncode(glm::vec3(0)), glm::vec2(kNoNormalCode));
    EXPECT_EQ(octahedralDecode(glm::vec2(kNoNormalCode)), glm::vec3(0));
    EXPECT_EQ(octahedralEncode(glm::vec3(NAN)), glm::vec2(kNoNormalCode));
}

TEST(GBufferLayouts, BytesPerPixel) {
    EXPECT_EQ(gbufferBytesPerPixel(GBufferLayout::compact), 12);
    EXPECT_EQ(gbufferBytesPerPixel(GBufferLayout::fat), 24);
    EXPECT_EQ(gbufferBytesPerPixel(GBufferLayout::fat32), 40);
    EXPECT_EQ(gbufferBytesPerPixel(GBufferLayout::rgba8Raw), 20);
    EXPECT_EQ(halfFloatSpacing(1000.0f), 0.5f);
    EXPECT_EQ(halfFloatSpacing(10000.0f), 8.0f);
}

TEST_F(DeferredHardCases, LightingMatchesTheFormulaForEveryKindOfNormal) {
    Scene scene = darkScene();
    // Pixel 0 faces the camera; 1 faces away from it (back-facing); 2 and 3 lie on the octahedral fold;
    // 4 points straight down (the code's corner); 5 has no normal at all.
    std::vector<glm::vec3> normals;
    for (int x = 0; x < kW; ++x) {
        glm::vec3 toEye = glm::normalize(scene.camera.position - worldAt(scene, x));
        normals.push_back(x == 0   ? toEye
                          : x == 1 ? -toEye
                          : x == 2 ? glm::vec3(0.6f, 0.8f, 0)
                          : x == 3 ? glm::vec3(-0.8f, 0, 0.6f)
                          : x == 4 ? glm::vec3(0, 0, -1)
                                   : glm::vec3(0));
    }
    normals[3] = glm::normalize(glm::vec3(-0.8f, -0.6f, 0));
    std::vector<glm::vec2> codes;
    std::vector<GpuPointLight> pointLights;
    for (int x = 0; x < kW; ++x) {
        codes.push_back(octahedralEncode(normals[std::size_t(x)]));
        // A light 0.4 m out along the normal's side (the camera's side for the normal-less pixel).
        glm::vec3 dir = x == 5 ? glm::vec3(0, 0, 1) : normals[std::size_t(x)];
        pointLights.push_back({glm::vec4(worldAt(scene, x) + 0.4f * dir, 1.0f), glm::vec4(2, 1, 0.5f, 0)});
    }
    FloatImage out = light(scene, codes, pointLights);
    ASSERT_FALSE(out.empty());
    ASSERT_TRUE(finite(out));
    for (int x = 0; x < kW; ++x) {
        // The normal the lighting pass sees: the code as RG16F stored it, decoded.
        glm::vec2 code = codes[std::size_t(x)];
        glm::vec3 stored = octahedralDecode(
            {glm::unpackHalf1x16(glm::packHalf1x16(code.x)), glm::unpackHalf1x16(glm::packHalf1x16(code.y))});
        glm::vec3 want(0);
        if (x != 5)
            for (const GpuPointLight& l : pointLights)
                want += expectedLight(scene, worldAt(scene, x), stored, l);
        expectNear(texel(out, x), want, cat("pixel ", x).c_str());
    }
    EXPECT_GT(texel(out, 1).r, 0.1f);        // a back-facing normal is lit from its own side...
    EXPECT_EQ(texel(out, 5), glm::vec3(0));  // ... and a missing normal is not lit at all
}

TEST_F(DeferredHardCases, RadiusZeroAddsNothingAndALightInsideTheSurfaceIsBounded) {
    Scene scene = darkScene();
    std::vector<glm::vec2> codes(kW, octahedralEncode(glm::vec3(0, 1, 0)));
    std::vector<GpuPointLight> pointLights;
    for (int x = 0; x < kW; ++x) {  // radius 0 at every pixel, on the surface and 10 cm above it
        pointLights.push_back({glm::vec4(worldAt(scene, x), 0.0f), glm::vec4(1000, 1000, 1000, 0)});
        pointLights.push_back(
            {glm::vec4(worldAt(scene, x) + glm::vec3(0, 0.1f, 0), 0.0f), glm::vec4(1000, 1000, 1000, 0)});
    }
    FloatImage none = light(scene, codes, pointLights);
    ASSERT_FALSE(none.empty());
    for (int x = 0; x < kW; ++x) EXPECT_EQ(texel(none, x), glm::vec3(0)) << x;

    pointLights.resize(kW);
    for (int x = 0; x < kW; ++x)  // now one light reaching 1 m, on the surface: d = 0
        pointLights[std::size_t(x)] = {glm::vec4(worldAt(scene, x), 1.0f), glm::vec4(1000, 1000, 1000, 0)};
    FloatImage inside = light(scene, codes, pointLights);
    ASSERT_TRUE(finite(inside));
    for (int x = 0; x < kW; ++x) {
        glm::vec3 c = texel(inside, x);
        // At the light: attenuation 1, lambert 1 (no direction: the normal's), specular at most 0.3.
        EXPECT_GE(c.r, 1000 * kAlbedo.r * 0.999f) << x;
        EXPECT_LE(c.r, 1000 * (kAlbedo.r + 0.3f) * 1.001f) << x;
    }
}

TEST_F(DeferredHardCases, AThousandLightsOnOnePixelStayFiniteAndClamped) {
    Scene scene = darkScene();
    std::vector<glm::vec2> codes(kW, octahedralEncode(glm::vec3(0, 0, 1)));
    std::vector<GpuPointLight> pointLights;
    for (int i = 0; i < kMaxGridLights; ++i)
        pointLights.push_back(
            {glm::vec4(worldAt(scene, i % kW) + glm::vec3(0, 0, 0.01f * float(i % 7)), 5.0f),
             glm::vec4(60000, 60000, 60000, 0)});
    FloatImage out = light(scene, codes, pointLights);
    ASSERT_FALSE(out.empty());
    ASSERT_TRUE(finite(out));
    for (int x = 0; x < kW; ++x) EXPECT_EQ(texel(out, x), glm::vec3(kSceneHdrMax)) << x;
}

// What storing the world position costs far from the origin (step 5): the fat layout's RGBA16F against
// the compact layout's depth reconstruction, both against the exact (RGBA32F) position.
TEST_F(DeferredHardCases, PositionErrorFarFromTheOrigin) {
    auto scene = loadShippedScene();
    ASSERT_TRUE(scene.ok()) << scene.error();
    SceneMeshes meshes(*scene);
    GBufferPass gbuffer = GBufferPass::create();
    const Size2D size{96, 54};
    GraphRunner runner(size.width, size.height);
    auto measure = [&](GBufferLayout layout, float offset) {
        FloatImage error = runner.run(size, [&](FrameGraph& graph) {
            GBufferTargets g =
                gbuffer.declare(graph, *scene, meshes, 0.0, {layout, true, glm::vec3(offset, 0, 0)});
            return lighting.declarePositionError(graph, *scene, g);
        });
        EXPECT_TRUE(finite(error));
        double sum = 0;
        float worst = 0;
        int covered = 0;
        for (int y = 0; y < size.height; ++y)
            for (int x = 0; x < size.width; ++x) {
                float e = error.texel(x, y, 3);
                if (error.texel(x, y, 0) + error.texel(x, y, 1) + error.texel(x, y, 2) == 0 && e == 0)
                    continue;
                sum += e;
                worst = std::max(worst, e);
                ++covered;
            }
        EXPECT_GT(covered, size.width * size.height / 2);
        float mean = covered ? float(sum / covered) : 0.0f;
        std::printf("position error, %s layout at %g m: mean %.6f m, max %.6f m\n", toString(layout), offset,
                    mean, worst);
        return mean;
    };
    float fat0 = measure(GBufferLayout::fat, 0), fat1k = measure(GBufferLayout::fat, 1000),
          fat10k = measure(GBufferLayout::fat, 10000);
    float compact0 = measure(GBufferLayout::compact, 0), compact1k = measure(GBufferLayout::compact, 1000),
          compact10k = measure(GBufferLayout::compact, 10000);
    // A half float's step is 0.5 m at 1 km and 8 m at 10 km: rounding costs up to half of it.
    EXPECT_LT(fat0, 0.01f);
    EXPECT_GT(fat1k, 0.05f);
    EXPECT_LT(fat1k, 0.4f);
    EXPECT_GT(fat10k, 1.0f);
    EXPECT_LT(fat10k, 6.0f);
    // Depth32F and a float inverse matrix: millimetres at 1 km, centimetres at 10 km (the float matrices
    // hold the 10 km translation to about a millimetre), a tenth of the fat layout's error or less.
    EXPECT_LT(compact0, 0.01f);
    EXPECT_LT(compact1k, fat1k / 10);
    EXPECT_LT(compact10k, fat10k / 10);
}

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
    ASSERT_TRUE(mrt.usable()) << mrt.error();
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
    RenderToTexture rtt = RenderToTexture::create();
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
    LectureMrt mrt = LectureMrt::create();
    ASSERT_TRUE(mrt.usable());
    GraphRunner runner(w, h);
    SharpenTargets targets;
    auto declare = [&](FrameGraph& graph) {
        MrtTargets t{d.import(graph, "mrt.diffuse"),
                     s.import(graph, "mrt.specular"),
                     a.import(graph, "mrt.ambient"),
                     {}};
        targets = mrt.declareSharpen(graph, scene, t);
        return targets.kept;
    };
    FloatImage kept = runner.run({w, h}, declare);
    FloatImage clipped = runner.run({w, h}, [&](FrameGraph& graph) {
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
    GBufferPass gbuffer = GBufferPass::create();
    const Size2D size{96, 54};
    GraphRunner runner(size.width, size.height);
    auto normals = [&](GBufferLayout layout) {
        return runner.run(size, [&](FrameGraph& graph) {
            return gbuffer.declare(graph, *scene, meshes, 0.0, {layout, false, glm::vec3(0)}).normal;
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
