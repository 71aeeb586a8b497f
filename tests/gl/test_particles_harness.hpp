#pragma once
// Particles on GL for tests/gl/test_particle*.cpp (lesson 07, Shader effects §3.8): the chapter's fire
// as a scene emitter, a target to draw sprites into, and the fixture with a renderer.
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <set>
#include <string>
#include "base/log.hpp"
#include "effects/particles/gpu_particles.hpp"
#include "effects/particles/particle_renderer.hpp"
#include "effects/particles/particle_system.hpp"
#include "effects/post/fullscreen_pass.hpp"
#include "gl/framebuffer.hpp"
#include "gl/readback.hpp"
#include "gl/texture.hpp"
#include "gl_test.hpp"

namespace fx::test {

// The chapter's FireParticle and FireEmitter (Shader effects §3.8) as a scene emitter.
inline ParticleEmitter chapterFire() {
    ParticleEmitter e;
    e.position = {0.0f, 0.0f, -4.0f};
    e.ratePerSecond = 5.0f;
    e.lifetimeSeconds = 1.0f;
    e.startSize = 0.5f;
    e.endSize = 2.0f;
    e.startColor = {3.0f, 0.8f, 0.2f, 1.0f};
    e.endColor = {3.0f, 0.8f, 0.2f, 0.0f};
    e.riseSpeed = 2.0f;
    e.seed = 7;
    return e;
}

inline EmitterSetup setupOf(ParticleEmitter e, bool chapter, int capacity = 0) {
    return {e, {chapter, chapter}, capacity, 1.0f, false};
}

// Alpha the draw would give a particle (the shader's particleLook, on the CPU).
inline float drawnAlpha(const GpuParticle& p, const GpuEmitter& e) {
    float t = p.originAge.w / p.velocityLife.w;
    if (e.motion.y == 0.0f) t = std::clamp(t, 0.0f, 1.0f);
    float a = e.startColor.a + (e.endColor.a - e.startColor.a) * t;
    return e.motion.y == 0.0f ? std::clamp(a, 0.0f, 1.0f) : a;
}

// A colour target (and depth) to draw particles into, cleared to `background`.
struct Target {
    gl::Texture color, depth;
    gl::Framebuffer fbo;
    int width, height;
    Target(int w, int h, TextureFormat format, glm::vec4 background) : width(w), height(h) {
        color = gl::Texture::create2D(format, w, h, 1, "test particles.target");
        depth = gl::Texture::create2D(TextureFormat::Depth32F, w, h, 1, "test particles.depth");
        fbo = gl::Framebuffer("test particles fbo");
        fbo.attachColor(0, color);
        fbo.attachDepth(depth);
        glClearNamedFramebufferfv(fbo.name(), GL_COLOR, 0, &background.x);
        float one = 1.0f;
        glClearNamedFramebufferfv(fbo.name(), GL_DEPTH, 0, &one);
    }
    void bind(bool premultiplied) const {
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.name());
        glViewport(0, 0, width, height);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        if (premultiplied)
            glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        else
            glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    }
    void unbind() const {
        glDisable(GL_BLEND);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    FloatImage read() const { return gl::readTexture(color); }
};

inline ParticleDrawSettings camera(int width, int height) {
    ParticleDrawSettings s;
    s.view = glm::mat4(1.0f);  // at the origin, looking down -z
    s.projection = glm::perspective(glm::radians(50.0f), float(width) / float(height), 0.1f, 100.0f);
    return s;
}

struct Extremes {
    float min = INFINITY, max = -INFINITY;
    bool finite = true;
};
inline Extremes extremes(const FloatImage& image, int channels = 3) {
    Extremes e;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < channels; ++c) {
                float v = image.texel(x, y, c);
                if (!std::isfinite(v)) e.finite = false;
                e.min = std::min(e.min, v);
                e.max = std::max(e.max, v);
            }
    return e;
}

class Particles : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        ASSERT_TRUE(programsBuilt());
    }
    ParticleRenderer renderer;
};

}  // namespace fx::test
