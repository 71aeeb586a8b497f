#pragma once
// The cloud pass on GL for tests/gl/test_clouds*.cpp (effects/clouds, the Clouds chapter's hard cases in
// its part 8), read back as floats. Most cases use a constant density texture, so the expected opacity
// is the chapter's closed form 1 - (1 - 0.3 a)^n for n samples in the slab.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <vector>
#include "base/paths.hpp"
#include "effects/clouds/cloud_march.hpp"
#include "effects/clouds/cloud_pass.hpp"
#include "effects/clouds/cloud_temporal.hpp"
#include "effects/scene/camera_matrices.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/shadow/shadow_map.hpp"
#include "gl/readback.hpp"
#include "gl_frame_runner.hpp"
#include "gl_test.hpp"
#include "image/png_file.hpp"
#include "scene/scene_loader.hpp"

namespace fx::test {

inline constexpr float kTolerance = 3e-3f;  // RGBA16F holds the result: about 1e-3 near 1

inline float srgbDecode(float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

// The chapter's opacity after n samples of density a (both layers summed), without threshold.
inline float chapterOpacity(float a, int n) {
    return 1.0f - std::pow(1.0f - std::min(0.3f * a, 1.0f), float(n));
}

inline ByteImage constantDensity(unsigned char value) {
    ByteImage image = makeByteImage(4, 4, 4);
    for (std::size_t i = 0; i < image.texels.size(); ++i) image.texels[i] = (i % 4 == 3) ? 255 : value;
    return image;
}

inline Camera cameraAt(glm::vec3 position, float yaw, float pitch) {
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
inline CloudFrameSettings marchSettings(const Camera& camera, int width, int height) {
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
inline float depthForViewZ(const glm::mat4& projection, float z) {
    glm::vec4 clip = projection * glm::vec4(0.0f, 0.0f, z, 1.0f);
    return clip.z / clip.w * 0.5f + 0.5f;
}

// The mean of |alpha(x) - alpha(y)| over two pictures of one size.
inline double meanAbsoluteAlphaDifference(const FloatImage& x, const FloatImage& y) {
    double sum = 0;
    for (int j = 0; j < x.height; ++j)
        for (int i = 0; i < x.width; ++i) sum += std::abs(x.texel(i, j, 3) - y.texel(i, j, 3));
    return sum / double(x.width * x.height);
}

class CloudsOnGl : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        ASSERT_TRUE(programsBuilt());
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

        GlFrameRunner({width, height}).frame([&](FrameGraph& graph) {
            TextureHandle c = graph.importTexture("scene.color", color.spec(), color.name());
            TextureHandle d = graph.importTexture("scene.depth", depth.spec(), depth.name());
            pass.declare(graph, {c, d, nullptr}, density, settings);
        });
        return gl::readTexture(color);
    }

    // Lesson 08's scene as shipped (a failed load fails the test).
    static Result<Scene> lessonScene() {
        SceneLoadOptions options;
        options.assetRoot = resourceDir();
        auto loaded = loadScene(resourceDir() / "scenes/08_clouds.json", options);
        EXPECT_TRUE(loaded.ok()) << (loaded.ok() ? "" : loaded.error());
        return loaded;
    }

    // The pass with object shadows from lesson 08's scene, its sun turned straight down (hard case 14),
    // over a colour target cleared to 0 and sky depth (1) everywhere. kPillar stands in the slab.
    static constexpr glm::vec3 kPillar{3.0f, 0.0f, -6.0f};  // "pillar 1": 1.2 m square, 5 m tall
    FloatImage runUnderTheSun(const CloudFrameSettings& settings, int width, int height,
                              const CloudDensityTexture& density) {
        auto loaded = lessonScene();
        if (!loaded.ok()) return {};
        Scene scene = std::move(*loaded);
        scene.lights.at(0).direction = {0.0f, -1.0f, 0.0f};
        SceneMeshes meshes(scene);
        ShadowMap shadows;
        EXPECT_TRUE(programsBuilt());
        gl::Texture color =
            gl::Texture::create2D(TextureFormat::RGBA16F, width, height, 1, "test.scene.color");
        gl::Texture depth =
            gl::Texture::create2D(TextureFormat::Depth32F, width, height, 1, "test.scene.depth");
        const float zero[4] = {0, 0, 0, 0};
        const float one = 1.0f;
        glClearTexImage(color.name(), 0, GL_RGBA, GL_FLOAT, zero);
        glClearTexImage(depth.name(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &one);

        GlFrameRunner({width, height}).frame([&](FrameGraph& graph) {
            TextureHandle c = graph.importTexture("scene.color", color.spec(), color.name());
            TextureHandle d = graph.importTexture("scene.depth", depth.spec(), depth.name());
            ShadowSettings shadowSettings = shadowCastingLight(scene)->shadow;
            DeclaredShadowMap map = shadows.declare(graph, World(scene, meshes, 0.0), shadowSettings, {});
            EXPECT_NE(map.pass, nullptr);
            EXPECT_FALSE(map.lookup.light.fallbackDirection);
            pass.declare(graph, {c, d, &map}, density, settings);
        });
        return gl::readTexture(color);
    }
    static float alphaAt(const FloatImage& image, int x, int y) { return image.texel(x, y, 3); }

    CloudPass pass;
    CloudDensityTexture constant;
    float a = 0.0f;
};

// The cloud density texture the lessons ship (res/textures/cloud_density.png).
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

}  // namespace fx::test
