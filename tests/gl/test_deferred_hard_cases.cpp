// Deferred shading's hard cases (Deferred rendering chapter, lesson 10), read back as floats: the
// lighting pass on a G-buffer the test writes texel by texel (zero-length, back-facing and fold
// normals, a light of radius 0, a light inside the surface, 1024 lights on one pixel) against a CPU
// evaluation of the same formula; the octahedral code; the position error of the fat and compact
// layouts 1,000 and 10,000 m from the origin. Framebuffers that would lose writes silently and the
// lecture's targets are in test_deferred_targets.cpp.
#include "effects/deferred/light_evaluations.hpp"
#include "effects/deferred/tiled_culling.hpp"
#include "test_deferred_harness.hpp"

using namespace fx;
using namespace fx::test;

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
    ASSERT_TRUE(allFinite(out));
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

// Hard case 3: shininess 0 and huge. Pixel 1 faces away from the eye with its light straight out along
// the normal, so the half vector l + v is zero and n.h is 0: pow(0, 0), which GLSL leaves undefined
// (llvmpipe's NaN turns the pixel black once the pass maps NaN to 0). The shader takes an exponent of 0 as
// a flat highlight (1 everywhere, the limit of x^s for s -> 0) and a huge one underflows to the limit, 0
// below n.h = 1; both match the CPU formula at every kind of normal.
TEST_F(DeferredHardCases, ShininessZeroAndHugeMatchTheirLimits) {
    Scene scene = darkScene();
    std::vector<glm::vec2> codes;
    std::vector<GpuPointLight> pointLights;
    std::vector<glm::vec3> normals;
    for (int x = 0; x < kW; ++x) {
        glm::vec3 toEye = glm::normalize(scene.camera.position - worldAt(scene, x));
        glm::vec3 n = x == 1   ? -toEye
                      : x == 2 ? glm::vec3(0, 1, 0)
                      : x == 3 ? glm::normalize(glm::vec3(1, 0, 1))
                               : toEye;
        normals.push_back(n);
        codes.push_back(octahedralEncode(n));
        pointLights.push_back({glm::vec4(worldAt(scene, x) + 0.4f * n, 1.0f), glm::vec4(2, 1, 0.5f, 0)});
    }
    for (float shininess : {0.0f, 1e30f}) {
        lighting = DeferredLighting(shininess);
        FloatImage out = light(scene, codes, pointLights);
        ASSERT_FALSE(out.empty());
        ASSERT_TRUE(allFinite(out));
        for (int x = 0; x < kW; ++x) {
            glm::vec2 code = codes[std::size_t(x)];
            glm::vec3 stored = octahedralDecode({glm::unpackHalf1x16(glm::packHalf1x16(code.x)),
                                                 glm::unpackHalf1x16(glm::packHalf1x16(code.y))});
            glm::vec3 want(0);
            for (const GpuPointLight& l : pointLights)
                want += expectedLight(scene, worldAt(scene, x), stored, l, shininess);
            expectNear(texel(out, x), want, cat("shininess ", shininess, ", pixel ", x).c_str());
        }
        // Pixel 1 (n.h = 0): lit, with the flat highlight at exponent 0 and none at a huge one.
        EXPECT_GT(texel(out, 1).r, 0.1f) << "shininess " << shininess;
    }
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
    ASSERT_TRUE(allFinite(inside));
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
    ASSERT_TRUE(allFinite(out));
    for (int x = 0; x < kW; ++x) EXPECT_EQ(texel(out, x), glm::vec3(kSceneHdrMax)) << x;
}

// What storing the world position costs far from the origin (step 5): the fat layout's RGBA16F against
// the compact layout's depth reconstruction, both against the exact (RGBA32F) position.
TEST_F(DeferredHardCases, PositionErrorFarFromTheOrigin) {
    auto scene = loadShippedScene();
    ASSERT_TRUE(scene.ok()) << scene.error();
    SceneMeshes meshes(*scene);
    GBufferPass gbuffer;
    const Size2D size{96, 54};
    GlFrameRunner runner(size);
    auto measure = [&](GBufferLayout layout, float offset) {
        FloatImage error = runner.frameAndRead([&](FrameGraph& graph) {
            GBufferTargets g =
                gbuffer.declare(graph, World(*scene, meshes, 0.0), {layout, true, glm::vec3(offset, 0, 0)});
            return lighting.declarePositionError(graph, *scene, g);
        });
        EXPECT_TRUE(allFinite(error));
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

// Hard case 20 on the lesson's scene (step 6: 1024 lamps of radius 1.1 m over the yard) at 320 x 180:
// without culling every pixel evaluates every light, W x H x N = 59 million; the tiles' lists, read back
// from cull.heat, leave a few lights a pixel.
TEST_F(DeferredHardCases, ManyLightsCostWidthTimesHeightTimesLightsUnlessCulled) {
    auto scene = loadShippedScene();
    ASSERT_TRUE(scene.ok()) << scene.error();
    SceneMeshes meshes(*scene);
    GBufferPass gbuffer;
    TiledCulling culling;
    ASSERT_TRUE(programsBuilt());
    lights.upload(gpuPointLights(allLights(*scene), kMaxGridLights));
    ASSERT_EQ(lights.count(), 1024);
    const Size2D size{320, 180};
    GlFrameRunner runner(size);
    FloatImage heat = runner.frameAndRead([&](FrameGraph& graph) {
        GBufferTargets g =
            gbuffer.declare(graph, World(*scene, meshes, 0.0), {GBufferLayout::compact, false, {}});
        return culling.declare(graph, *scene, g, lights).heat;
    });
    ASSERT_FALSE(heat.empty());
    ASSERT_EQ(heat.width, tileCount(size).width);
    std::vector<float> perTile;
    for (int y = 0; y < heat.height; ++y)
        for (int x = 0; x < heat.width; ++x) perTile.push_back(heat.texel(x, y, 0));
    const std::int64_t naive = naiveLightEvaluations(size, lights.count());
    const std::int64_t tiled = tiledLightEvaluations(size, perTile);
    std::printf(
        "light evaluations at 320 x 180 with 1024 lights: %lld without culling, %lld tiled (%.1f a pixel)\n",
        (long long)naive, (long long)tiled, double(tiled) / (size.width * size.height));
    EXPECT_EQ(naive, 320LL * 180 * 1024);
    EXPECT_GT(tiled, 0);
    EXPECT_LT(tiled * 20, naive);  // the lamps reach 1.1 m: a tile sees a few dozen at most
}
