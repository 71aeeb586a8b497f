// The cloud pass on GL (effects/clouds, the Clouds chapter's hard cases in its part 8), read back as
// floats. Most cases use a constant density texture, so the expected opacity is the chapter's closed
// form 1 - (1 - 0.3 a)^n for n samples in the slab; the rest use the generated cloud texture.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "base/paths.hpp"
#include "effects/clouds/cloud_march.hpp"
#include "effects/clouds/cloud_pass.hpp"
#include "effects/clouds/cloud_temporal.hpp"
#include "effects/scene/camera_matrices.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/shadow/shadow_map.hpp"
#include "gl/readback.hpp"
#include "gl_test.hpp"
#include "image/png_file.hpp"
#include "render_gl/gl_pass_executor.hpp"
#include "render_gl/gl_texture_allocator.hpp"
#include "render_gl/pass_timer.hpp"
#include "scene/scene_loader.hpp"

using namespace fx;

namespace {

constexpr float kTolerance = 3e-3f;  // RGBA16F holds the result: about 1e-3 near 1

float srgbDecode(float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

// The chapter's opacity after n samples of density a (both layers summed), without threshold.
float chapterOpacity(float a, int n) {
    return 1.0f - std::pow(1.0f - std::min(0.3f * a, 1.0f), float(n));
}

ByteImage constantDensity(unsigned char value) {
    ByteImage image = makeByteImage(4, 4, 4);
    for (std::size_t i = 0; i < image.texels.size(); ++i) image.texels[i] = (i % 4 == 3) ? 255 : value;
    return image;
}

Camera cameraAt(glm::vec3 position, float yaw, float pitch) {
    Camera c;
    c.position = position;
    c.aim = CameraAim::yawPitch;
    c.yawDegrees = yaw;
    c.pitchDegrees = pitch;
    c.fovYDegrees = 60.0f;
    c.near = 0.1f;
    c.far = 500.0f;
    return c;
}

// Step 6's march (two scales, depth, eye inside), no dither, the chapter's slab 0..2 m and 8 samples.
CloudFrameSettings marchSettings(const Camera& camera, int width, int height) {
    CloudFrameSettings s;
    s.stage = CloudStage::march;
    s.features = cloudTwoScales | cloudDepthAware | cloudEyeInside;
    s.march = cloudMarch(0.0f, 2.0f, 8.0f, 0.5f);
    s.scales = {1.0f / 311.0f, 1.0f / 127.0f};
    s.color = glm::vec3(1.0f);
    CameraMatrices m = cameraMatrices(camera, width, height);
    s.view = m.view;
    s.projection = m.projection;
    s.cameraPosition = m.position;
    return s;
}

// The depth a camera's depth buffer holds for a point at view-space depth z (z < 0).
float depthForViewZ(const glm::mat4& projection, float z) {
    glm::vec4 clip = projection * glm::vec4(0.0f, 0.0f, z, 1.0f);
    return clip.z / clip.w * 0.5f + 0.5f;
}

class CloudsOnGl : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        pass = CloudPass::create();
        ASSERT_TRUE(pass.usable()) << pass.error();
        constant = CloudDensityTexture::fromImage(constantDensity(188));
        a = 2.0f * srgbDecode(188.0f / 255.0f);
    }

    // Runs the pass over a colour target cleared to 0 with `depth01` as the scene's depth (empty: 1
    // everywhere, the sky). Returns the colour target: alpha is the cloud's opacity.
    FloatImage run(const CloudFrameSettings& settings, int width, int height,
                   const CloudDensityTexture& density, std::vector<float> depth01 = {}) {
        gl::Texture color =
            gl::Texture::create2D(TextureFormat::RGBA16F, width, height, 1, "test.scene.color");
        gl::Texture depth =
            gl::Texture::create2D(TextureFormat::Depth32F, width, height, 1, "test.scene.depth");
        const float zero[4] = {0, 0, 0, 0};
        glClearTexImage(color.name(), 0, GL_RGBA, GL_FLOAT, zero);
        if (depth01.empty()) depth01.assign(std::size_t(width) * std::size_t(height), 1.0f);
        glTextureSubImage2D(depth.name(), 0, 0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT,
                            depth01.data());

        FrameGraph graph(OutputTarget{{width, height}, "output", TextureFormat::RGBA8, 0});
        TextureHandle c = graph.importTexture("scene.color", color.spec(), color.name());
        TextureHandle d = graph.importTexture("scene.depth", depth.spec(), depth.name());
        pass.declare(graph, {c, d, nullptr}, density, settings);
        Status status = graph.execute(pool, executor);
        EXPECT_TRUE(status) << (status ? "" : status.error());
        graph.releaseTextures();
        pool.endFrame();
        glDisable(GL_BLEND);
        glUseProgram(0);
        glBindVertexArray(0);
        return gl::readTexture(color);
    }

    static bool allFinite(const FloatImage& image) {
        return std::all_of(image.texels.begin(), image.texels.end(),
                           [](float v) { return std::isfinite(v); });
    }
    static float alphaAt(const FloatImage& image, int x, int y) { return image.texel(x, y, 3); }

    CloudPass pass;
    CloudDensityTexture constant;
    float a = 0.0f;
    GlTextureAllocator allocator;
    TexturePool pool{allocator};
    PassTimer timer{TimingMode::Off, ""};
    GlPassExecutor executor{timer, {0, true}};
};

TEST_F(CloudsOnGl, LookingDownFromAboveEveryRayTakesAllEightSamples) {
    Camera cam = cameraAt({0, 5, 0}, 0, -89.5f);
    FloatImage out = run(marchSettings(cam, 3, 3), 3, 3, constant);
    ASSERT_TRUE(allFinite(out));
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x)
            EXPECT_NEAR(alphaAt(out, x, y), chapterOpacity(a, 8), kTolerance) << x << "," << y;
    // rgb = colour x opacity over a black target: the colour is white.
    EXPECT_NEAR(out.texel(1, 1, 0), alphaAt(out, 1, 1), kTolerance);
}

TEST_F(CloudsOnGl, EyeInsideTheSlabMarchesFromTheEyeOnlyWithTheChaptersFix) {
    // Eye at 1.1 m looking down: samples at 1.1, 0.85, 0.6, 0.35, 0.1 m are in the slab, the rest below it.
    Camera cam = cameraAt({0, 1.1f, 0}, 0, -89.5f);
    CloudFrameSettings fixed = marchSettings(cam, 3, 3);
    FloatImage out = run(fixed, 3, 3, constant);
    ASSERT_TRUE(allFinite(out));
    EXPECT_NEAR(alphaAt(out, 1, 1), chapterOpacity(a, 5), kTolerance);
    // Step 5 (before the fix): the bottom face is ahead but the top face behind, tmin < 0: nothing.
    CloudFrameSettings before = fixed;
    before.features &= ~cloudEyeInside;
    FloatImage none = run(before, 3, 3, constant);
    EXPECT_EQ(alphaAt(none, 1, 1), 0.0f);
}

TEST_F(CloudsOnGl, ARayParallelToTheSlabIsFiniteInsideOnTheFacesAndOutside) {
    // An odd height puts the middle row's pixel centres exactly on the horizon: v.y == 0.
    const int w = 5, h = 5;
    struct Case {
        float eyeY;
        float expected;
    };
    for (Case c : {Case{1.0f, chapterOpacity(a, 8)}, Case{0.0f, chapterOpacity(a, 8)},
                   Case{2.0f, chapterOpacity(a, 8)}, Case{3.0f, 0.0f}, Case{-1.0f, 0.0f}}) {
        Camera cam = cameraAt({0, c.eyeY, 0}, 0, 0);
        FloatImage out = run(marchSettings(cam, w, h), w, h, constant);
        ASSERT_TRUE(allFinite(out)) << "eye at " << c.eyeY;
        for (int x = 0; x < w; ++x)
            EXPECT_NEAR(alphaAt(out, x, h / 2), c.expected, kTolerance) << "eye at " << c.eyeY << ", x " << x;
    }
}

TEST_F(CloudsOnGl, EyeOnTheTopFaceLookingDownStartsAtTheEye) {
    Camera cam = cameraAt({0, 2.0f, 0}, 0, -89.5f);
    FloatImage out = run(marchSettings(cam, 3, 3), 3, 3, constant);
    ASSERT_TRUE(allFinite(out));
    EXPECT_NEAR(alphaAt(out, 1, 1), chapterOpacity(a, 8), kTolerance);
}

TEST_F(CloudsOnGl, DepthFromASurfaceStopsTheRayThereAndSkyDoesNot) {
    Camera cam = cameraAt({0, 5, 0}, 0, -89.5f);
    CloudFrameSettings s = marchSettings(cam, 3, 3);
    // A surface 1 m under the eye (above the slab) hides it all; one at 1.1 m height (3.9 m under the
    // eye) leaves the samples at 2, 1.75, 1.5 and 1.25 m.
    std::vector<float> above(9, depthForViewZ(s.projection, -1.0f));
    std::vector<float> inside(9, depthForViewZ(s.projection, -3.9f));
    FloatImage hidden = run(s, 3, 3, constant, above);
    FloatImage partly = run(s, 3, 3, constant, inside);
    ASSERT_TRUE(allFinite(hidden));
    ASSERT_TRUE(allFinite(partly));
    EXPECT_EQ(alphaAt(hidden, 1, 1), 0.0f);
    EXPECT_NEAR(alphaAt(partly, 1, 1), chapterOpacity(a, 4), kTolerance);
    // Sky (depth exactly 1): the whole slab.
    FloatImage sky = run(s, 3, 3, constant, std::vector<float>(9, 1.0f));
    EXPECT_NEAR(alphaAt(sky, 1, 1), chapterOpacity(a, 8), kTolerance);
}

TEST_F(CloudsOnGl, ALevelRayInsideTheSlabStopsAtANearbyWallOnlyByDistance) {
    // Hard case 4: the eye inside the slab looking level at a wall 3 m away. The chapter's height test
    // cannot tell in front from behind when y does not change along the ray: all 8 samples count,
    // 20 m of them through the wall. Compared by distance, only the samples at 0 and 2.5 m do.
    const int w = 5, h = 5;
    Camera cam = cameraAt({0, 1, 0}, 0, 0);
    CloudFrameSettings s = marchSettings(cam, w, h);
    std::vector<float> wall(std::size_t(w * h), depthForViewZ(s.projection, -3.0f));
    FloatImage byHeight = run(s, w, h, constant, wall);
    s.features |= cloudDistanceOcclusion;
    FloatImage byDistance = run(s, w, h, constant, wall);
    ASSERT_TRUE(allFinite(byHeight));
    ASSERT_TRUE(allFinite(byDistance));
    EXPECT_NEAR(alphaAt(byHeight, w / 2, h / 2), chapterOpacity(a, 8), kTolerance);
    EXPECT_NEAR(alphaAt(byDistance, w / 2, h / 2), chapterOpacity(a, 2), kTolerance);
}

TEST_F(CloudsOnGl, ThresholdOneEqualFacesAndNoSamplesGiveNoCloudAndNoNaN) {
    Camera cam = cameraAt({0, 5, 0}, 0, -89.5f);
    CloudFrameSettings base = marchSettings(cam, 3, 3);
    base.features |= cloudThreshold | cloudHeightShaping | cloudShadows;

    CloudFrameSettings threshold1 = base;
    threshold1.march = cloudMarch(0.0f, 2.0f, 8.0f, 1.0f);
    CloudFrameSettings flat = base;
    flat.march = cloudMarch(1.0f, 1.0f, 8.0f, 0.5f);
    CloudFrameSettings noSamples = base;
    noSamples.march = cloudMarch(0.0f, 2.0f, 0.0f, 0.5f);
    for (const CloudFrameSettings* s : {&threshold1, &flat, &noSamples}) {
        FloatImage out = run(*s, 3, 3, constant);
        ASSERT_TRUE(allFinite(out));
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 3; ++x) EXPECT_EQ(alphaAt(out, x, y), 0.0f);
    }
    // Just below 1: a huge gain, every sample clamped to full opacity, still finite.
    CloudFrameSettings almost = base;
    almost.march = cloudMarch(0.0f, 2.0f, 8.0f, 0.9999f);
    FloatImage out = run(almost, 3, 3, constant);
    ASSERT_TRUE(allFinite(out));
    EXPECT_LE(alphaAt(out, 1, 1), 1.0f);
}

TEST_F(CloudsOnGl, OneSampleAndANonIntegerCount) {
    Camera cam = cameraAt({0, 5, 0}, 0, -89.5f);
    CloudFrameSettings one = marchSettings(cam, 3, 3);
    one.march = cloudMarch(0.0f, 2.0f, 1.0f, 0.5f);
    EXPECT_NEAR(alphaAt(run(one, 3, 3, constant), 1, 1), chapterOpacity(a, 1), kTolerance);
    CloudFrameSettings eightAndAHalf = marchSettings(cam, 3, 3);
    eightAndAHalf.march = cloudMarch(0.0f, 2.0f, 8.5f, 0.5f);
    EXPECT_NEAR(alphaAt(run(eightAndAHalf, 3, 3, constant), 1, 1), chapterOpacity(a, 8), kTolerance);
}

TEST_F(CloudsOnGl, BeerLambertConvergesWithTheSampleCount) {
    // Beyond the chapter: opacity from each step's length, so 16 and 512 samples agree, where the
    // chapter's constant 0.3 a sample would go from 0.6 to fully opaque.
    Camera cam = cameraAt({0, 5, 0}, 0, -89.5f);
    CloudFrameSettings s = marchSettings(cam, 3, 3);
    s.features |= cloudBeerLambert;
    s.march = cloudMarch(0.0f, 2.0f, 16.0f, 0.5f);
    float at16 = alphaAt(run(s, 3, 3, constant), 1, 1);
    s.march = cloudMarch(0.0f, 2.0f, 512.0f, 0.5f);
    float at512 = alphaAt(run(s, 3, 3, constant), 1, 1);
    // Exactly 1 - exp(-sigma a L): sigma = 0.3 x 8 / thickness, L the slab's 2 m (straight down).
    float exact = 1.0f - std::exp(-0.3f * 8.0f / 2.0f * a * 2.0f);
    EXPECT_NEAR(at16, exact, 5e-3f);
    EXPECT_NEAR(at512, exact, 5e-3f);
}

TEST_F(CloudsOnGl, HitsBehindTheEyeAreRejectedOtherwiseTheLayerIsMirroredInTheSky) {
    // The plane at 1 m, the eye at 6 m looking up: every hit is behind the eye.
    Camera cam = cameraAt({0, 6, 0}, 0, 35.0f);
    CloudFrameSettings s = marchSettings(cam, 8, 8);
    s.stage = CloudStage::plane;
    s.planeHeight = 1.0f;
    s.features = cloudRejectBehind;
    FloatImage rejected = run(s, 8, 8, constant);
    s.features = 0;
    FloatImage mirrored = run(s, 8, 8, constant);
    ASSERT_TRUE(allFinite(rejected));
    ASSERT_TRUE(allFinite(mirrored));
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x) {
            EXPECT_EQ(alphaAt(rejected, x, y), 0.0f);
            EXPECT_GT(alphaAt(mirrored, x, y), 0.1f);
        }
    }
}

// The stage, the features, the dither and the premultiplied output are #defines (one program each,
// so llvmpipe does not run every alternative); a bit or a dither the stage's code never reads must not
// build another program for the same picture.
TEST_F(CloudsOnGl, SettingsThatDrawTheSamePictureShareOneProgram) {
    CloudFrameSettings screen;
    screen.stage = CloudStage::screenTexture;
    CloudFrameSettings screenWithEverything = screen;
    screenWithEverything.features = cloudShadows | cloudTwoScales | cloudBeerLambert;
    screenWithEverything.dither = CloudDither::r2;
    EXPECT_EQ(&pass.programFor(screen), &pass.programFor(screenWithEverything));

    CloudFrameSettings plane;
    plane.stage = CloudStage::plane;
    plane.features = cloudRejectBehind | cloudTwoScales;
    CloudFrameSettings planeWithMarchBits = plane;
    planeWithMarchBits.features |= cloudShadows | cloudEyeInside | cloudBeerLambert;
    planeWithMarchBits.dither = CloudDither::bayer;
    EXPECT_EQ(&pass.programFor(plane), &pass.programFor(planeWithMarchBits));
    EXPECT_NE(&pass.programFor(plane), &pass.programFor(screen));

    // What the march reads is a program of its own: the dither, a feature bit, premultiplied output.
    CloudFrameSettings march;
    march.stage = CloudStage::march;
    march.features = cloudEyeInside;
    CloudFrameSettings bayer = march;
    bayer.dither = CloudDither::bayer;
    CloudFrameSettings shadows = march;
    shadows.features |= cloudShadows;
    CloudFrameSettings premultiplied = march;
    premultiplied.premultiplied = true;
    CloudFrameSettings rejectBehind = march;  // a plane-only bit: the same march
    rejectBehind.features |= cloudRejectBehind;
    const FullscreenPass* m = &pass.programFor(march);
    EXPECT_NE(m, &pass.programFor(bayer));
    EXPECT_NE(m, &pass.programFor(shadows));
    EXPECT_NE(m, &pass.programFor(premultiplied));
    EXPECT_EQ(m, &pass.programFor(rejectBehind));
    for (const CloudFrameSettings* s : {&screen, &plane, &march, &bayer, &shadows, &premultiplied})
        EXPECT_TRUE(pass.programFor(*s).usable()) << pass.programFor(*s).error();
}

TEST_F(CloudsOnGl, TheWorldPositionFromDepthUsesTheMatricesThatDrewIt) {
    // A floor under the eye, its depth written as a camera would: at 0.5 m (under the plane at 1 m)
    // the plane is in front of it; at 1.5 m the floor is in front of the plane and hides it.
    const int w = 16, h = 16;
    Camera cam = cameraAt({0, 6, 0}, 20, -40);
    CloudFrameSettings s = marchSettings(cam, w, h);
    s.stage = CloudStage::plane;
    s.planeHeight = 1.0f;
    s.features = cloudRejectBehind | cloudDepthAware;
    glm::mat4 inverseViewProjection = glm::inverse(s.projection * s.view);
    auto floorDepth = [&](float floorY) {
        std::vector<float> depth(std::size_t(w * h), 1.0f);
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                glm::vec4 ndc((x + 0.5f) / w * 2 - 1, (y + 0.5f) / h * 2 - 1, 1.0f, 1.0f);
                glm::vec4 farPoint = inverseViewProjection * ndc;
                glm::vec3 dir = glm::normalize(glm::vec3(farPoint) / farPoint.w - s.cameraPosition);
                if (dir.y >= 0) continue;
                glm::vec3 hit = s.cameraPosition + dir * ((floorY - s.cameraPosition.y) / dir.y);
                glm::vec4 clip = s.projection * s.view * glm::vec4(hit, 1.0f);
                depth[std::size_t(y * w + x)] = clip.z / clip.w * 0.5f + 0.5f;
            }
        }
        return depth;
    };
    FloatImage below = run(s, w, h, constant, floorDepth(0.5f));
    FloatImage above = run(s, w, h, constant, floorDepth(1.5f));
    ASSERT_TRUE(allFinite(below));
    ASSERT_TRUE(allFinite(above));
    std::vector<float> depthBelow = floorDepth(0.5f);
    int floorPixels = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (depthBelow[std::size_t(y * w + x)] >= 1.0f) continue;
            ++floorPixels;
            EXPECT_GT(alphaAt(below, x, y), 0.1f) << x << "," << y;
            EXPECT_EQ(alphaAt(above, x, y), 0.0f) << x << "," << y;
        }
    }
    EXPECT_GT(floorPixels, w * h / 2);
}

TEST_F(CloudsOnGl, AJitterAveragedOverFramesConvergesToManySamples) {
    // A floor inside the slab cuts every ray at another height: with 8 samples its opacity comes in
    // bands. Interleaved gradient noise moves the start every frame; averaged over 16 frames (with
    // reprojection, the camera still) the error against 512 samples falls well below one frame's.
    const int w = 32, h = 24;
    Camera cam = cameraAt({0, 5, 0}, 0, -40);
    CloudFrameSettings s = marchSettings(cam, w, h);
    s.features |= cloudBeerLambert | cloudDistanceOcclusion;
    glm::mat4 inverseViewProjection = glm::inverse(s.projection * s.view);
    std::vector<float> floorDepth(std::size_t(w * h), 1.0f);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            glm::vec4 far =
                inverseViewProjection * glm::vec4((x + 0.5f) / w * 2 - 1, (y + 0.5f) / h * 2 - 1, 1, 1);
            glm::vec3 dir = glm::normalize(glm::vec3(far) / far.w - s.cameraPosition);
            if (dir.y >= 0) continue;
            glm::vec3 hit = s.cameraPosition + dir * ((0.7f - s.cameraPosition.y) / dir.y);
            glm::vec4 clip = s.projection * s.view * glm::vec4(hit, 1.0f);
            floorDepth[std::size_t(y * w + x)] = clip.z / clip.w * 0.5f + 0.5f;
        }
    }
    CloudFrameSettings reference = s;
    reference.march = cloudMarch(0.0f, 2.0f, 512.0f, 0.5f);
    FloatImage truth = run(reference, w, h, constant, floorDepth);

    gl::Texture color = gl::Texture::create2D(TextureFormat::RGBA16F, w, h, 1, "test.scene.color");
    gl::Texture depth = gl::Texture::create2D(TextureFormat::Depth32F, w, h, 1, "test.scene.depth");
    glTextureSubImage2D(depth.name(), 0, 0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, floorDepth.data());
    CloudTemporal temporal = CloudTemporal::create();
    ASSERT_TRUE(temporal.usable());
    auto rmse = [&](const FloatImage& x) {
        double sum = 0;
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) sum += std::pow(double(x.texel(i, j, 3) - truth.texel(i, j, 3)), 2.0);
        return std::sqrt(sum / double(w * h));
    };
    double firstError = 0, lastError = 0;
    for (int frame = 0; frame < 16; ++frame) {
        const float zero[4] = {0, 0, 0, 0};
        glClearTexImage(color.name(), 0, GL_RGBA, GL_FLOAT, zero);
        CloudFrameSettings f = s;
        f.dither = CloudDither::ign;
        f.frameIndex = frame;
        FrameGraph graph(OutputTarget{{w, h}, "output", TextureFormat::RGBA8, 0});
        TextureHandle c = graph.importTexture("scene.color", color.spec(), color.name());
        TextureHandle d = graph.importTexture("scene.depth", depth.spec(), depth.name());
        temporal.declare(graph, pass, {c, d, nullptr}, constant, f, {true, false}, 1u, {w, h});
        Status status = graph.execute(pool, executor);
        ASSERT_TRUE(status) << status.error();
        graph.releaseTextures();
        pool.endFrame();
        FloatImage out = gl::readTexture(color);
        ASSERT_TRUE(allFinite(out));
        (frame == 0 ? firstError : lastError) = rmse(out);
    }
    glDisable(GL_BLEND);
    EXPECT_EQ(temporal.framesAveraged(), 16);
    EXPECT_GT(firstError, 0.01);  // one frame of 8 jittered samples is visibly off
    EXPECT_LT(lastError, 0.5 * firstError);
}

TEST_F(CloudsOnGl, TheSunStraightOverheadShadowsTheCloudUnderAPillar) {
    // The lesson's scene with the sun straight down: a look-at with up = +Y would have no sideways axis
    // (hard case 14). Seen from above, rays through the pillar's footprint cross slab samples in its
    // shadow (the depth is left at 1, so the pillar does not hide them); rays beside it do not.
    SceneLoadOptions options;
    options.assetRoot = resourceDir();
    auto loaded = loadScene(resourceDir() / "scenes/08_clouds.json", options);
    ASSERT_TRUE(loaded.ok()) << (loaded.ok() ? "" : loaded.error());
    Scene scene = std::move(*loaded);
    scene.lights.at(0).direction = {0.0f, -1.0f, 0.0f};
    const glm::vec3 pillar{3.0f, 0.0f, -6.0f};  // "pillar 1": 1.2 m square, 5 m tall
    SceneMeshes meshes(scene);
    ShadowMap shadows = ShadowMap::create();
    ASSERT_TRUE(shadows.usable()) << shadows.error();

    const int w = 33, h = 33;
    Camera cam = cameraAt({pillar.x, 12.0f, pillar.z}, 0, -89.5f);
    CloudFrameSettings s = marchSettings(cam, w, h);
    s.features |= cloudShadows;
    gl::Texture color = gl::Texture::create2D(TextureFormat::RGBA16F, w, h, 1, "test.scene.color");
    gl::Texture depth = gl::Texture::create2D(TextureFormat::Depth32F, w, h, 1, "test.scene.depth");
    const float zero[4] = {0, 0, 0, 0};
    const float one = 1.0f;
    glClearTexImage(color.name(), 0, GL_RGBA, GL_FLOAT, zero);
    glClearTexImage(depth.name(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &one);

    FrameGraph graph(OutputTarget{{w, h}, "output", TextureFormat::RGBA8, 0});
    TextureHandle c = graph.importTexture("scene.color", color.spec(), color.name());
    TextureHandle d = graph.importTexture("scene.depth", depth.spec(), depth.name());
    ShadowSettings settings = shadowCastingLight(scene)->shadow;
    DeclaredShadowMap map = shadows.declare(graph, scene, meshes, 0.0, settings, {});
    ASSERT_NE(map.pass, nullptr);
    EXPECT_FALSE(map.lookup.light.fallbackDirection);
    pass.declare(graph, {c, d, &map}, constant, s);
    Status status = graph.execute(pool, executor);
    ASSERT_TRUE(status) << status.error();
    graph.releaseTextures();
    pool.endFrame();
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    FloatImage out = gl::readTexture(color);
    ASSERT_TRUE(allFinite(out));
    // rgb = colour x (1 - shadow) x opacity: rgb / alpha is the light reaching the cloud.
    auto light = [&](int x, int y) { return out.texel(x, y, 0) / std::max(alphaAt(out, x, y), 1e-6f); };
    EXPECT_GT(alphaAt(out, w / 2, h / 2), 0.5f);
    EXPECT_LT(light(w / 2, h / 2), 0.8f);
    EXPECT_GT(light(2, 2), 0.95f);
    EXPECT_GT(light(w - 3, h - 3), 0.95f);
}

class CloudsWithTheGeneratedTexture : public CloudsOnGl {
protected:
    void SetUp() override {
        CloudsOnGl::SetUp();
        auto loaded = CloudDensityTexture::load((resourceDir() / "textures/cloud_density.png").string());
        ASSERT_TRUE(loaded) << loaded.error();
        texture = std::move(*loaded);
    }
    CloudDensityTexture texture;
};

double meanAbsoluteAlphaDifference(const FloatImage& x, const FloatImage& y) {
    double sum = 0;
    for (int j = 0; j < x.height; ++j)
        for (int i = 0; i < x.width; ++i) sum += std::abs(x.texel(i, j, 3) - y.texel(i, j, 3));
    return sum / double(x.width * x.height);
}

TEST_F(CloudsWithTheGeneratedTexture, ACamera10KmFromTheOriginSeesTheSameClouds) {
    // 1/256 and 1/128 repeats per metre: 10.24 km is a whole number of repeats of both layers.
    const int w = 24, h = 16;
    Camera home = cameraAt({0, 5, 0}, 30, -30);
    Camera away = cameraAt({10240.0f, 5, -10240.0f}, 30, -30);
    CloudFrameSettings s0 = marchSettings(home, w, h), s1 = marchSettings(away, w, h);
    s0.scales = s1.scales = {1.0f / 256.0f, 1.0f / 128.0f};
    FloatImage near = run(s0, w, h, texture), far = run(s1, w, h, texture);
    ASSERT_TRUE(allFinite(far));
    // What is left comes from the camera's own matrices (a look-at from a position of 10240 m keeps
    // about 1e-3 m of it), not from the texture coordinates.
    double same = meanAbsoluteAlphaDifference(near, far);
    CloudFrameSettings moved = marchSettings(cameraAt({0.5f, 5, 0}, 30, -30), w, h);
    moved.scales = s0.scales;
    double halfMetre = meanAbsoluteAlphaDifference(near, run(moved, w, h, texture));
    std::printf("10 km: mean |difference| %g, camera moved 0.5 m: %g\n", same, halfMetre);
    EXPECT_LT(same, 2e-3);
    EXPECT_GT(halfMetre, 5.0 * same);  // the comparison sees a camera moved by half a metre
}

TEST_F(CloudsWithTheGeneratedTexture, AClockAt200HoursScrollsAsFarPerSecondAsInTheFirstMinute) {
    // After 200 hours of scrolling, one more second of 60 frames (advanced as the lesson does) must
    // move the clouds by speed x 1 s, exactly as in the first minute: the picture equals the one drawn
    // with the offset moved by that amount in one go. The chapter's unwrapped float stalls there.
    const int w = 48, h = 32;
    const glm::dvec4 start{0.0, 0.0, 0.3, 0.7}, speed{-0.0019, -0.0041, -0.0027, -0.0013};
    Camera cam = cameraAt({0, 5, 0}, 0, -35);
    for (double seconds : {60.0, 200.0 * 3600.0}) {
        CloudScroll scroll = CloudScroll::at(start, speed, seconds);
        CloudFrameSettings s = marchSettings(cam, w, h);
        s.scrollOffset = scroll.offset();
        FloatImage before = run(s, w, h, texture);
        CloudScroll oneStep = scroll;
        oneStep.advance(speed, 1.0);
        for (int i = 0; i < 60; ++i) scroll.advance(speed, 1.0 / 60.0);
        s.scrollOffset = scroll.offset();
        FloatImage framed = run(s, w, h, texture);
        s.scrollOffset = oneStep.offset();
        FloatImage expected = run(s, w, h, texture);
        ASSERT_TRUE(allFinite(framed));
        EXPECT_LT(meanAbsoluteAlphaDifference(framed, expected), 1e-4) << seconds << " s";
        EXPECT_GT(meanAbsoluteAlphaDifference(framed, before), 5e-3) << seconds << " s";  // it moved
    }
}

}  // namespace
