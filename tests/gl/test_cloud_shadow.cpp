// Cloud shadows on the ground (effects/clouds/cloud_shadow_pass.hpp), read back as floats: the
// transmittance map "clouds.shadow" over a flat floor, with a density texture that is empty, dense or
// dense in one patch, and the sun overhead or at a grazing angle.
#include <algorithm>
#include <cmath>
#include <vector>

#include "effects/clouds/cloud_march.hpp"
#include "effects/clouds/cloud_pass.hpp"
#include "effects/clouds/cloud_shadow_pass.hpp"
#include "effects/scene/camera_matrices.hpp"
#include "gl/readback.hpp"
#include "gl_frame_runner.hpp"
#include "gl_test.hpp"

using namespace fx;

namespace {

constexpr int kSize = 16;

// A density texture of `side` x `side` texels: `dense` inside [lo, hi) on both axes, 0 elsewhere.
ByteImage patchDensity(int side, int lo, int hi, unsigned char dense) {
    ByteImage image = makeByteImage(side, side, 4);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            unsigned char* t = &image.texels[std::size_t((y * side + x) * 4)];
            bool in = x >= lo && x < hi && y >= lo && y < hi;
            t[0] = t[1] = t[2] = in ? dense : 0;
            t[3] = 255;
        }
    return image;
}

// A camera 10 m above a floor at y = 0, looking straight down; the slab is 20..40 m, above the camera.
CloudFrameSettings settingsLookingDown() {
    Camera c;
    c.position = {0.0f, 10.0f, 0.0f};
    c.aim = CameraAim::yawPitch;
    c.yawDegrees = 0.0f;
    c.pitchDegrees = -90.0f;
    c.fovYDegrees = 60.0f;
    c.near = 0.1f;
    c.far = 500.0f;
    CloudFrameSettings s;
    s.march = cloudMarch(20.0f, 40.0f, 8.0f, 0.3f);
    s.scales = {1.0f / 1000.0f, 1.0f / 1000.0f};  // one texture repeat per km: the floor sees one texel
    CameraMatrices m = cameraMatrices(c, kSize, kSize);
    s.view = m.view;
    s.projection = m.projection;
    s.cameraPosition = m.position;
    return s;
}

// The depth of the floor (y = 0) at every pixel, written as the camera's depth buffer would hold it.
std::vector<float> floorDepth(const CloudFrameSettings& s) {
    std::vector<float> depth(std::size_t(kSize * kSize), 1.0f);
    glm::mat4 viewProjection = s.projection * s.view;
    glm::mat4 inverse = glm::inverse(viewProjection);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            glm::vec2 ndc((x + 0.5f) / kSize * 2.0f - 1.0f, (y + 0.5f) / kSize * 2.0f - 1.0f);
            glm::vec4 nearPoint = inverse * glm::vec4(ndc, -1.0f, 1.0f);
            glm::vec4 farPoint = inverse * glm::vec4(ndc, 1.0f, 1.0f);
            glm::vec3 a = glm::vec3(nearPoint) / nearPoint.w, b = glm::vec3(farPoint) / farPoint.w;
            float t = a.y / (a.y - b.y);  // where the pixel's ray meets y = 0
            glm::vec4 clip = viewProjection * glm::vec4(a + (b - a) * t, 1.0f);
            depth[std::size_t(y * kSize + x)] = clip.z / clip.w * 0.5f + 0.5f;
        }
    return depth;
}

class CloudShadowOnGl : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        ASSERT_TRUE(programsBuilt());
    }

    // The map over the floor (or the sky where `sky`), as floats.
    FloatImage run(const CloudFrameSettings& s, const CloudDensityTexture& density, glm::vec3 toLight,
                   bool sky = false) {
        gl::Texture depth =
            gl::Texture::create2D(TextureFormat::Depth32F, kSize, kSize, 1, "test.scene.depth");
        std::vector<float> d = sky ? std::vector<float>(std::size_t(kSize * kSize), 1.0f) : floorDepth(s);
        glTextureSubImage2D(depth.name(), 0, 0, 0, kSize, kSize, GL_DEPTH_COMPONENT, GL_FLOAT, d.data());

        FloatImage result;
        test::GlFrameRunner({kSize, kSize}).frame([&](FrameGraph& graph) {
            TextureHandle dh = graph.importTexture("scene.depth", depth.spec(), depth.name());
            TextureHandle map = pass.declareMap(graph, dh, density, s, {toLight, 0.7f, kCloudShadowSamples});
            graph
                .addPass(
                    "read back",
                    [map, &result](PassContext& ctx) {
                        result = gl::readTexture(ctx.native(map), {kSize, kSize, TextureFormat::R16F, 1});
                    })
                .read(map)
                .keepAlive();
        });
        return result;
    }

    static float minOf(const FloatImage& image) {
        float m = 2.0f;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) m = std::min(m, image.texel(x, y, 0));
        return m;
    }
    static float maxOf(const FloatImage& image) {
        float m = -1.0f;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) m = std::max(m, image.texel(x, y, 0));
        return m;
    }
    static bool finiteInUnitRange(const FloatImage& image) {
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                float v = image.texel(x, y, 0);
                if (!std::isfinite(v) || v < 0.0f || v > 1.0f) return false;
            }
        return true;
    }

    CloudShadowPass pass;
};

TEST_F(CloudShadowOnGl, NoCloudLetsAllTheSunThroughExactly) {
    CloudFrameSettings s = settingsLookingDown();
    CloudDensityTexture empty = CloudDensityTexture::fromImage(patchDensity(4, 0, 0, 0));
    FloatImage overhead = run(s, empty, {0.0f, 1.0f, 0.0f});
    EXPECT_EQ(minOf(overhead), 1.0f);
    EXPECT_EQ(maxOf(overhead), 1.0f);
    // A dense sky but the floor above the slab (slab lowered under the floor): nothing in the way.
    CloudDensityTexture dense = CloudDensityTexture::fromImage(patchDensity(4, 0, 4, 255));
    CloudFrameSettings below = s;
    below.march = cloudMarch(-40.0f, -20.0f, 8.0f, 0.3f);
    EXPECT_EQ(minOf(run(below, dense, {0.0f, 1.0f, 0.0f})), 1.0f);
    // Sky pixels (depth exactly 1) get no cloud shadow.
    EXPECT_EQ(minOf(run(s, dense, {0.0f, 1.0f, 0.0f}, true)), 1.0f);
}

TEST_F(CloudShadowOnGl, UnderADensePatchTheSunIsDimmedByBeerLambert) {
    CloudFrameSettings s = settingsLookingDown();
    CloudDensityTexture dense = CloudDensityTexture::fromImage(patchDensity(4, 0, 4, 255));
    FloatImage t = run(s, dense, {0.0f, 1.0f, 0.0f});
    EXPECT_TRUE(finiteInUnitRange(t));
    // Density 1 in both layers (a = 2), shaped by height (x 0.5 at the top to x 1 at the bottom), the
    // threshold 0.3 taken off and clamped to 1, then x 1 / 0.7; 8 midpoint samples of 2.5 m up a
    // vertical path, at the clouds' extinction 0.3 x 8 / 20 m per unit of density.
    double opticalDepth = 0.0;
    for (int i = 0; i < 8; ++i) {
        double shape = 1.0 - (i + 0.5) / 8.0;
        double a = 2.0 * (0.5 * shape + 0.5);
        opticalDepth += 0.12 * std::min(a - 0.3, 1.0) / 0.7 * 2.5;
    }
    const float expected = float(std::exp(-opticalDepth));
    for (int y = 0; y < kSize; y += 5)
        for (int x = 0; x < kSize; x += 5) EXPECT_NEAR(t.texel(x, y, 0), expected, 1e-3f) << x << "," << y;
}

TEST_F(CloudShadowOnGl, OnlyThePatchCastsAShadow) {
    // One dense texel of 16 at the texture's corner region: with one repeat per km the floor under the
    // camera (x, z within a few metres of 0) samples texel (0, 0): the patch covers texels 0..7.
    CloudFrameSettings s = settingsLookingDown();
    CloudDensityTexture patch = CloudDensityTexture::fromImage(patchDensity(16, 8, 16, 255));
    // The floor is around uv 0 (the texel corner shared by 4 texels); shift the layers by hand so
    // that the floor sits in the middle of the patch, then in the middle of the clear part.
    s.scrollOffset = glm::vec4(0.75f, 0.75f, 0.75f, 0.75f);
    EXPECT_LT(maxOf(run(s, patch, {0.0f, 1.0f, 0.0f})), 0.2f);
    s.scrollOffset = glm::vec4(0.25f, 0.25f, 0.25f, 0.25f);
    EXPECT_EQ(minOf(run(s, patch, {0.0f, 1.0f, 0.0f})), 1.0f);
}

TEST_F(CloudShadowOnGl, AGrazingOrLowSunStaysFiniteAndInRange) {
    CloudFrameSettings s = settingsLookingDown();
    CloudDensityTexture dense = CloudDensityTexture::fromImage(patchDensity(4, 0, 4, 255));
    for (glm::vec3 toLight :
         {glm::vec3(1.0f, 1e-6f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 0.05f, 1.0f),
          glm::vec3(1.0f, 1e-30f, 1.0f), glm::vec3(0.0f, 0.0f, 0.0f)}) {
        FloatImage t = run(s, dense, toLight);
        EXPECT_TRUE(finiteInUnitRange(t)) << toLight.x << "," << toLight.y << "," << toLight.z;
    }
    // Clear air at a grazing sun: 0 density over an unguarded (infinite) path would be 0 x inf = NaN.
    CloudDensityTexture empty = CloudDensityTexture::fromImage(patchDensity(4, 0, 0, 0));
    EXPECT_EQ(minOf(run(s, empty, {1.0f, 1e-30f, 0.0f})), 1.0f);
    CloudDensityTexture patch = CloudDensityTexture::fromImage(patchDensity(16, 8, 16, 255));
    EXPECT_TRUE(finiteInUnitRange(run(s, patch, {1.0f, 1e-30f, 1.0f})));
    // A sun exactly on the horizon lights nothing directly: no cloud shadow to cast.
    EXPECT_EQ(minOf(run(s, dense, {1.0f, 0.0f, 0.0f})), 1.0f);
    // A sun at 45 degrees crosses the slab on a path sqrt(2) times as long as an overhead one.
    float overhead = maxOf(run(s, dense, {0.0f, 1.0f, 0.0f}));
    FloatImage low = run(s, dense, {1.0f, 1.0f, 0.0f});
    EXPECT_NEAR(maxOf(low), std::pow(overhead, std::sqrt(2.0f)), 1e-3f);
    EXPECT_NEAR(minOf(low), maxOf(low), 1e-3f);
    // A zero-length direction means straight up (cloudShadowToLight).
    EXPECT_NEAR(minOf(run(s, dense, {0.0f, 0.0f, 0.0f})), overhead, 1e-3f);
}

TEST_F(CloudShadowOnGl, ASunBelowTheGuardsSlopeCrossesAtMostTenSlabThicknesses) {
    // A faint constant density and no threshold, so a long path is still measurable: a sun 0.6 degrees
    // up would cross 100 thicknesses; the guard (sine 0.1, as the clouds' own march) makes it 10.
    CloudFrameSettings s = settingsLookingDown();
    s.march = cloudMarch(20.0f, 40.0f, 8.0f, 0.0f);
    CloudDensityTexture faint = CloudDensityTexture::fromImage(patchDensity(4, 0, 4, 20));
    float overhead = maxOf(run(s, faint, {0.0f, 1.0f, 0.0f}));
    ASSERT_LT(overhead, 0.99f);
    FloatImage low = run(s, faint, {1.0f, 0.01f, 0.0f});
    EXPECT_NEAR(minOf(low), std::pow(overhead, 10.0f), 2e-3f);
    EXPECT_NEAR(maxOf(low), std::pow(overhead, 10.0f), 2e-3f);
}

TEST(CloudShadowToLight, TurnsTheTravelDirectionAroundAndGuardsZero) {
    glm::vec3 up = cloudShadowToLight({0.0f, -2.0f, 0.0f});
    EXPECT_FLOAT_EQ(up.y, 1.0f);
    glm::vec3 none = cloudShadowToLight({0.0f, 0.0f, 0.0f});
    EXPECT_FLOAT_EQ(none.y, 1.0f);
    glm::vec3 nan = cloudShadowToLight({std::nanf(""), 0.0f, 0.0f});
    EXPECT_FLOAT_EQ(nan.y, 1.0f);
}

}  // namespace
