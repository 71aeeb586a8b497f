// The Shader effects chapter's fire (§3.8, lesson 07) in the picture, read back as floats: one chapter
// particle over its second (rises 2 m, grows from 0.5 m to 2 m wide, alpha 1 to 0, about 5 alive),
// Exercise 06's 120 degrees a second as the sprite's turn, the spawn order against back to front
// (hard case 24), the opaque flame's (255, 230, 123) without bloom, and alpha x 3 < 1 leaving the
// bloom's bright pass (threshold 1) with nothing.
#include <filesystem>
#include <numbers>
#include <numeric>

#include <glm/gtc/matrix_transform.hpp>

#include "base/paths.hpp"
#include "effects/bloom/bloom_settings.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "image/png_file.hpp"
#include "scene/scene_loader.hpp"
#include "test_bloom_harness.hpp"
#include "test_particles_harness.hpp"

using namespace fx;
using namespace fx::test;

namespace {

// The campfire of lesson 07's scene: the chapter's FireParticle and FireEmitter as data.
ParticleEmitter sceneCampfire() {
    SceneLoadOptions options;
    options.assetRoot = resourceDir();
    auto loaded = loadScene(resourceDir() / "scenes/07_fire_emitter.json", options);
    EXPECT_TRUE(loaded.ok()) << (loaded.ok() ? "" : loaded.error());
    if (!loaded.ok()) return chapterFire();
    for (const ParticleEmitter& e : loaded->emitters)
        if (e.name == "campfire") return e;
    ADD_FAILURE() << "lesson 07's scene has no emitter named campfire";
    return chapterFire();
}

// Looking down -z with an orthographic view of x in [-2, 2], y in [-1, 3] (16 pixels a metre on a
// 64x64 target), so a particle's width and height read straight off the picture in metres.
ParticleDrawSettings orthographic(float left, float right, float bottom, float top) {
    ParticleDrawSettings s;
    s.view = glm::mat4(1.0f);
    s.projection = glm::ortho(left, right, bottom, top, 0.1f, 100.0f);
    return s;
}

// A sprite file whose alpha is `alpha(x, y)` (y: the picture's row, 0 at the bottom, as fx images count;
// writePng stores it last).
template <class F>
std::filesystem::path writeSprite(const std::string& name, int size, F alpha) {
    ByteImage image = makeByteImage(size, size, 4, 255);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            image.texels[std::size_t((y * size + x) * 4 + 3)] = std::uint8_t(alpha(x, y));
    std::filesystem::path path = std::filesystem::path(::testing::TempDir()) / ("fxlab-" + name + ".png");
    Status written = writePng(path, image);
    EXPECT_TRUE(written) << (written ? "" : written.error());
    return path;
}

class FireChapter : public Particles {
protected:
    // The particles drawn in the given order over black (straight alpha, the chapter's blend).
    FloatImage draw(const ParticleSystem& system, const std::vector<GpuParticle>& particles,
                    const ParticleDrawSettings& settings, int width, int height,
                    TextureFormat format = TextureFormat::RGBA32F) {
        Target target(width, height, format, {0, 0, 0, 0});
        renderer.setEmitters(system.emitters());
        target.bind(false);
        renderer.drawInstanced(particles, settings);
        target.unbind();
        return target.read();
    }
    static GpuParticle at(const ParticleEmitter& e, glm::vec3 origin, float age) {
        GpuParticle p = ParticleSystem::spawnParticle(e, 0, 0, age);
        p.originAge = glm::vec4(origin, age);
        return p;
    }
};

struct Box {
    int minX = 1 << 30, maxX = -1, minY = 1 << 30, maxY = -1;
    float peak = 0.0f;  // the largest red value
};
Box coverage(const FloatImage& image) {
    Box b;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            b.peak = std::max(b.peak, image.texel(x, y, 0));
            if (image.texel(x, y, 3) <= 1e-4f) continue;
            b.minX = std::min(b.minX, x);
            b.maxX = std::max(b.maxX, x);
            b.minY = std::min(b.minY, y);
            b.maxY = std::max(b.maxY, y);
        }
    return b;
}

// One particle that stays where it is born, opaque and 2 m wide, drawn with the loaded sprite.
EmitterSetup stillSprite(ParticleEmitter e) {
    e.riseSpeed = 0.0f;
    e.startColor.a = e.endColor.a = 1.0f;
    e.startSize = e.endSize = 2.0f;
    EmitterSetup setup = setupOf(e, false);
    setup.textured = true;
    return setup;
}

// The alpha's mass and its first moments about the picture's centre (in pixels, rows bottom-up): where
// a half-opaque sprite's mass lies says which way it points.
struct AlphaMass {
    double x = 0, y = 0, sum = 0;
};
AlphaMass alphaMass(const FloatImage& image) {
    AlphaMass m;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const double a = image.texel(x, y, 3);
            m.x += a * (x + 0.5 - 0.5 * image.width);
            m.y += a * (y + 0.5 - 0.5 * image.height);
            m.sum += a;
        }
    return m;
}

}  // namespace

TEST_F(FireChapter, OneParticleRisesTwoMetresGrowsFourfoldAndFadesOverItsSecond) {
    ParticleEmitter e = sceneCampfire();
    // The chapter's numbers as the scene gives them: one spawn every 0.2 s, 1 s of life, 2 m/s up,
    // scale 0.25 to 1.0 of a +-1 quad (0.5 m to 2 m wide), emission (3, 0.8, 0.2), alpha 1 to 0.
    EXPECT_EQ(e.ratePerSecond, 5.0f);
    EXPECT_EQ(e.lifetimeSeconds, 1.0f);
    EXPECT_EQ(e.riseSpeed, 2.0f);
    EXPECT_EQ(e.startSize, 0.5f);
    EXPECT_EQ(e.endSize, 2.0f);
    EXPECT_EQ(e.spread, 0.0f);
    EXPECT_EQ(e.startColor, glm::vec4(3.0f, 0.8f, 0.2f, 1.0f));
    EXPECT_EQ(e.endColor, glm::vec4(3.0f, 0.8f, 0.2f, 0.0f));

    ParticleSystem system({setupOf(e, false)});  // a soft dot: alpha 1 inside a fifth of the radius
    const ParticleDrawSettings view = orthographic(-2, 2, -1, 3);
    for (float age : {0.0f, 0.25f, 0.5f, 0.9f}) {
        FloatImage image = draw(system, {at(e, {0, 0, -10}, age)}, view, 64, 64);
        Box b = coverage(image);
        ASSERT_GE(b.maxX, 0) << "nothing drawn at age " << age;
        const float width = float(b.maxX - b.minX + 1) / 16.0f;
        const float centreY = float(b.minY + b.maxY + 1) / 2.0f / 16.0f - 1.0f;
        EXPECT_NEAR(width, 0.5f + 1.5f * age, 2.0f / 16.0f) << "width at age " << age;
        EXPECT_NEAR(centreY, 2.0f * age, 1.0f / 16.0f) << "height at age " << age;
        EXPECT_NEAR(b.peak, 3.0f * (1.0f - age), 0.01f) << "emission x alpha at age " << age;
    }

    // About five alive: one born every 0.2 s, each gone after 1 s. The chapter's rules draw a particle
    // once more on the frame its life ends, so five or six.
    for (bool chapter : {false, true}) {
        ParticleSystem fire({setupOf(e, chapter)});
        fire.prewarm(2.0);
        double sum = 0;
        std::uint32_t lowest = 100, highest = 0;
        for (int frame = 0; frame < 120; ++frame) {
            fire.update(1.0 / 60.0);
            sum += fire.liveCount();
            lowest = std::min(lowest, fire.liveCount());
            highest = std::max(highest, fire.liveCount());
        }
        EXPECT_NEAR(sum / 120.0, chapter ? 5.1 : 5.0, 0.15) << (chapter ? "chapter" : "fixed") << " rules";
        EXPECT_GE(lowest, chapter ? 5u : 4u);
        EXPECT_LE(highest, chapter ? 6u : 5u);
    }
}

TEST_F(FireChapter, Exercise06Turns120DegreesASecondThatIs2Point0944RadiansInThePicture) {
    // A sprite opaque in the bottom half of the picture only: where its mass lies says its angle.
    ASSERT_TRUE(
        renderer.loadSprite(writeSprite("half-sprite", 32, [](int, int y) { return y < 16 ? 255 : 0; })));
    ParticleEmitter e = chapterFire();
    e.spinDegreesPerSecond = 120.0f;
    e.lifetimeSeconds = 4.0f;
    const EmitterSetup still = stillSprite(e);  // stays at the centre
    ParticleSystem system({still});
    EXPECT_NEAR(system.emitters()[0].motion.x, 2.0944f, 1e-4f) << "radians a second";

    const ParticleDrawSettings view = orthographic(-2, 2, -2, 2);
    auto angleAt = [&](float age) {
        const AlphaMass m = alphaMass(draw(system, {at(still.emitter, {0, 0, -10}, age)}, view, 64, 64));
        EXPECT_GT(m.sum, 100.0) << "age " << age;
        return std::atan2(m.y, m.x);
    };
    const double start = angleAt(0.0f);
    // The picture's bottom row is the sprite's v = 0, the bottom of the quad (the texture's origin): the
    // chapter's sprite is stored the right way up (docs/assets.md), and a loader that uploads the file's
    // top row first turns the flame over (ASpriteUploadedTopRowFirstTurnsTheParticleUpsideDown).
    EXPECT_NEAR(start, -std::numbers::pi / 2, 0.02);
    for (float age : {0.25f, 0.5f, 0.75f, 1.0f, 1.5f}) {
        double turned = std::remainder(angleAt(age) - start, 2.0 * std::numbers::pi);
        double expected = std::remainder(2.0943951 * double(age), 2.0 * std::numbers::pi);
        EXPECT_NEAR(turned, expected, 0.03) << "age " << age;
    }
}

TEST_F(FireChapter, ASpriteUploadedTopRowFirstTurnsTheParticleUpsideDown) {
    // Opaque in the picture's bottom half (the image's rows run bottom-up): upright, the mass lies below
    // the particle's centre; uploaded in the file's order (lesson 07's flip_sprite), above it.
    const auto sprite = writeSprite("bottom-half-sprite", 32, [](int, int y) { return y < 16 ? 255 : 0; });
    const EmitterSetup still = stillSprite(chapterFire());
    ParticleSystem system({still});
    auto massRow = [&](ParticleRenderer::SpriteRows rows) {
        EXPECT_TRUE(renderer.loadSprite(sprite, rows));
        const AlphaMass m = alphaMass(
            draw(system, {at(still.emitter, {0, 0, -10}, 0.0f)}, orthographic(-2, 2, -2, 2), 64, 64));
        EXPECT_GT(m.sum, 100.0);
        return m.y / std::max(m.sum, 1.0);  // pixels above the centre
    };
    EXPECT_NEAR(massRow(ParticleRenderer::SpriteRows::bottomFirst), -8.0, 1.0) << "upright: a quarter down";
    EXPECT_NEAR(massRow(ParticleRenderer::SpriteRows::topFirst), 8.0, 1.0) << "top row first: upside down";
}

TEST_F(FireChapter, SpawnOrderBlendsTheFarParticleOverTheNearOneAndBackToFrontDoesNot) {
    // The colour says which particle is on top: red when young, blue when old, alpha 0.8 throughout.
    ParticleEmitter e = chapterFire();
    e.startColor = {4.0f, 0.0f, 0.0f, 0.8f};
    e.endColor = {0.0f, 0.0f, 4.0f, 0.8f};
    e.startSize = e.endSize = 2.0f;
    e.riseSpeed = 0.0f;
    ParticleSystem system({setupOf(e, false)});
    // Spawn order is oldest first (ParticleSystem::collect, the chapter's transparent queue).
    ParticleSystem spawning({setupOf(e, false)});
    spawning.update(1.0);
    std::vector<GpuParticle> live;
    spawning.collect(live);
    ASSERT_GE(live.size(), 2u);
    for (std::size_t i = 1; i < live.size(); ++i) EXPECT_GE(live[i - 1].originAge.w, live[i].originAge.w);

    // The older particle near (3 m), the younger far (6 m), both on the view axis.
    std::vector<GpuParticle> particles = {at(e, {0, 0, -3}, 0.9f), at(e, {0, 0, -6}, 0.1f)};
    // 17 x 17: the centre pixel (8, 8) lies on the view axis, inside both dots' opaque cores.
    const ParticleDrawSettings view = camera(17, 17);
    FloatImage spawnOrder = draw(system, particles, view, 17, 17);
    ParticleSystem::sortBackToFront(particles, view.view);
    EXPECT_EQ(particles[0].originAge.z, -6.0f) << "farthest first";
    FloatImage sorted = draw(system, particles, view, 17, 17);
    // Near over far: 0.8 x near + 0.2 x 0.8 x far. Spawn order puts the far (red) one on top.
    auto red = [](const FloatImage& i) { return i.texel(8, 8, 0); };
    auto blue = [](const FloatImage& i) { return i.texel(8, 8, 2); };
    EXPECT_NEAR(blue(sorted), 0.8f * 3.6f + 0.2f * 0.8f * 0.4f, 0.01f);
    EXPECT_NEAR(red(sorted), 0.8f * 0.4f + 0.2f * 0.8f * 3.6f, 0.01f);
    EXPECT_NEAR(red(spawnOrder), 0.8f * 3.6f + 0.2f * 0.8f * 0.4f, 0.01f);
    EXPECT_NEAR(blue(spawnOrder), 0.8f * 0.4f + 0.2f * 0.8f * 3.6f, 0.01f);
}

TEST_F(FireChapter, TheOpaqueFlameWithoutBloomShowsAbout255_230_123) {
    ParticleEmitter e = sceneCampfire();
    e.startSize = 2.0f;  // wide enough that the centre pixel lies inside the dot's opaque core
    ParticleSystem system({setupOf(e, false)});
    // At age 0 the dot's centre is opaque: scene.color (RGBA16F) holds the emission (3, 0.8, 0.2). On a
    // 17 x 17 target the centre pixel (8, 8) is the particle's centre.
    FloatImage scene =
        draw(system, {at(e, {0, 0, -10}, 0.0f)}, orthographic(-2, 2, -2, 2), 17, 17, TextureFormat::RGBA16F);
    EXPECT_NEAR(scene.texel(8, 8, 0), 3.0f, 2e-3f);
    EXPECT_NEAR(scene.texel(8, 8, 1), 0.8f, 1e-3f);
    EXPECT_NEAR(scene.texel(8, 8, 2), 0.2f, 1e-3f);
    OutputTransformPass present;
    ASSERT_TRUE(programsBuilt());
    EffectRunner runner(17, 17);
    runner.run(scene, TextureFormat::RGBA16F, [&](FrameGraph& g, TextureHandle in) {
        present.declare(g, in, std::nullopt, ToneCurve::clip);  // steps 1 and 2: the chapter's clip
        return in;
    });
    ASSERT_TRUE(runner.lastError.empty()) << runner.lastError;
    EXPECT_EQ(int(runner.presented.texel(8, 8, 0)), 255);  // 3.0 clips
    EXPECT_NEAR(int(runner.presented.texel(8, 8, 1)), 230, 1);
    EXPECT_NEAR(int(runner.presented.texel(8, 8, 2)), 123, 1);
}

TEST_F(FireChapter, AParticleStopsGlowingOnceAlphaTimesThreeIsBelowOne) {
    // A sprite opaque everywhere and a particle wider than the view: every pixel is the emission (3, 0.8,
    // 0.2) x alpha over black, and the chapter's bright pass (threshold 1) sees 3 x alpha.
    ASSERT_TRUE(renderer.loadSprite(writeSprite("opaque-sprite", 8, [](int, int) { return 255; })));
    ParticleEmitter e = sceneCampfire();
    e.startSize = e.endSize = 8.0f;
    e.riseSpeed = 0.0f;
    EmitterSetup setup = setupOf(e, false);
    setup.textured = true;
    ParticleSystem system({setup});
    BloomEffects effects;
    ASSERT_TRUE(programsBuilt());
    EffectRunner runner(32, 16);
    auto brightest = [&](float alpha) {
        FloatImage scene = draw(system, {at(e, {0, 0, -10}, 1.0f - alpha)}, orthographic(-2, 2, -1, 1), 32,
                                16, TextureFormat::RGBA16F);
        EXPECT_NEAR(scene.texel(16, 8, 0), 3.0f * alpha, 3e-3f);
        BloomChainSettings settings = shaderEffectsChain(1.0f, 2.0f, 6);
        settings.format = TextureFormat::RGBA32F;
        FloatImage bright = runChain(runner, effects, scene, TextureFormat::RGBA16F, settings,
                                     [](const BloomChain::Declared& d) { return d.down[0]; });
        EXPECT_TRUE(runner.lastError.empty()) << runner.lastError;
        return extremes(bright).max;
    };
    EXPECT_EQ(brightest(0.30f), 0.0f) << "3 x 0.30 = 0.9: below the threshold, no glow";
    EXPECT_EQ(brightest(0.33f), 0.0f) << "3 x 0.33 = 0.99";
    EXPECT_GT(brightest(0.34f), 0.0f) << "3 x 0.34 = 1.02: it glows";
    EXPECT_NEAR(brightest(0.5f), 2.0f * (1.5f - 1.0f), 0.01f)
        << "red 1.5: the chapter's ratio (1.5 - 1) / 1.5 keeps the hue, times the intensity 2";
}
