#pragma once
// Deferred shading on GL for tests/gl/test_deferred_*.cpp (Deferred rendering chapter, lesson 10): a
// G-buffer the test writes texel by texel, the frame graph run on the GL executor as a lesson runs it,
// and a CPU evaluation of the lighting formula to compare with.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>
#include <vector>
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
#include "gl_frame_runner.hpp"
#include "gl_test.hpp"
#include "scene/scene_loader.hpp"
#include "test_fullscreen_harness.hpp"

namespace fx::test {

inline constexpr int kW = 6, kH = 1;
// Exact in RGBA8 (153, 102 and 51 over 255), so the stored albedo is the one the CPU side uses.
inline const glm::vec3 kAlbedo(0.6f, 0.4f, 0.2f);

// A scene with no light but the point lights the test gives: a black sun (setFrameUniforms would
// otherwise use a default white one), no ambient, the default camera.
inline Scene darkScene() {
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
inline glm::vec3 worldAt(const Scene& scene, int x, float depth = 0.5f) {
    CameraMatrices c = cameraMatrices(scene.camera, kW, kH);
    glm::vec4 ndc((float(x) + 0.5f) / kW * 2 - 1, 0.5f / kH * 2 - 1, depth * 2 - 1, 1);
    glm::vec4 h = glm::inverse(c.viewProjection) * ndc;
    return glm::vec3(h) / h.w;
}

// The lighting pass's point-light formula on the CPU (point_lights.glsl), for one light.
inline glm::vec3 expectedLight(const Scene& scene, glm::vec3 p, glm::vec3 n, const GpuPointLight& light,
                               float shininess = kDefaultShininess) {
    glm::vec3 toLight = glm::vec3(light.positionRadius) - p;
    float d = glm::length(toLight), r = light.positionRadius.w;
    if (!(r > 0) || d >= r) return glm::vec3(0);
    float w = 1 - (d / r) * (d / r), att = w * w;
    glm::vec3 l = d > 1e-4f ? toLight / d : n;
    float lambert = std::max(glm::dot(n, l), 0.0f);
    if (lambert <= 0) return glm::vec3(0);
    glm::vec3 v = glm::normalize(scene.camera.position - p);
    glm::vec3 h = l + v;
    float nh = glm::length(h) > 1e-6f ? std::max(glm::dot(n, glm::normalize(h)), 0.0f) : 0.0f;
    float falloff = shininess > 0 ? std::pow(nh, shininess) : 1.0f;  // x^0 = 1, also at x = 0
    return att * glm::vec3(light.color) * (kAlbedo * lambert + 0.3f * falloff);
}

class DeferredHardCases : public GlTest {
protected:
    void SetUp() override { GlTest::SetUp(); }

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
        GlFrameRunner runner({kW, kH});
        return runner.frameAndRead([&](FrameGraph& graph) {
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

inline glm::vec3 texel(const FloatImage& image, int x) {
    return {image.texel(x, 0, 0), image.texel(x, 0, 1), image.texel(x, 0, 2)};
}

inline void expectNear(glm::vec3 got, glm::vec3 want, const char* what) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(got[c], want[c], 2e-3f * std::max(1.0f, std::abs(want[c]))) << what << " channel " << c;
}

}  // namespace fx::test
