// Particles (lesson 07, Shader effects §3.8 and hard cases 22 to 25): the GPU simulation and the sprite
// draw, read back as floats. An empty and a full pool, a long frame's alpha, a particle at the camera
// and at the near plane, additive light past a half float's range, the soft fade's distance 0 and its
// linearised depth, every source with every fade and blend, and a sprite that is not on disk. The CPU
// simulation's clock is in test_particle_clock.cpp.
#include "effects/scene/scene_bindings.hpp"
#include "test_particles_harness.hpp"

using namespace fx;
using namespace fx::test;

namespace {

// --- The GPU simulation ---

TEST_F(Particles, GpuSimulationMatchesTheCpuAndRepeats) {
    ParticleEmitter e = chapterFire();
    e.spread = 0.7f;  // the seeded hash decides velocities and angles
    e.spinDegreesPerSecond = 120.0f;
    ParticleEmitter second = chapterFire();
    second.ratePerSecond = 40.0f;
    second.seed = 99;
    second.position = {1, 0, -5};
    std::vector<EmitterSetup> setups = {setupOf(e, false), setupOf(second, false, 16)};
    ParticleSystem cpu(setups);
    ParticleSystem clocks(setups, false);
    renderer.setEmitters(clocks.emitters());
    GpuParticles gpu(clocks);
    ASSERT_TRUE(programsBuilt());
    const double steps[] = {1.0 / 60, 1.0 / 60, 0.0, 0.5, 1.0 / 60, 1.0, 1.0 / 30, 1.0 / 60};
    for (double dt : steps) {
        cpu.update(dt);
        clocks.update(dt);
        renderer.setEmitters(clocks.emitters());
        gpu.simulate(clocks, dt, renderer.emitterBuffer());
    }
    GpuParticleStats stats = gpu.readStats();
    EXPECT_EQ(stats.live, cpu.liveCount());
    EXPECT_EQ(stats.replaced, cpu.replacedCount());
    EXPECT_GT(stats.replaced, 0u);  // the second emitter's 16 slots overflow
    EXPECT_EQ(cpu.droppedCount(), clocks.droppedCount());
    EXPECT_GT(clocks.droppedCount(), 0u);  // its 0.5 s and 1 s frames owe more than 16 spawns at once
    std::vector<GpuParticle> pool = gpu.readPool();
    // Slot by slot, the GPU's pool against the CPU's; the draw list holds the live slots in order.
    ASSERT_EQ(pool.size(), cpu.slots().size());
    std::vector<std::uint32_t> expectedList;
    for (std::size_t i = 0; i < pool.size(); ++i) {
        const GpuParticle &g = pool[i], &c = cpu.slots()[i];
        ASSERT_EQ(g.extra.z, c.extra.z) << "slot " << i;
        if (c.extra.z == 0.0f) continue;
        expectedList.push_back(std::uint32_t(i));
        for (int k = 0; k < 4; ++k) {
            EXPECT_NEAR(c.originAge[k], g.originAge[k], 1e-5f) << "slot " << i;
            EXPECT_NEAR(c.velocityLife[k], g.velocityLife[k], 1e-5f) << "slot " << i;
            EXPECT_NEAR(c.extra[k], g.extra[k], 1e-5f) << "slot " << i;
        }
    }
    EXPECT_EQ(gpu.readLiveList(), expectedList);
    // The indirect draw's command: four vertices per particle, exactly the live ones.
    EXPECT_EQ(gpu.readDrawCommand(),
              (std::array<std::uint32_t, 4>{4, std::uint32_t(expectedList.size()), 0, 0}));
    // The inspector's picture of the pool (particles.pool) is the same from either side.
    const int rows = int((cpu.capacity() + 255) / 256);
    gl::Texture view = gl::Texture::create2D(TextureFormat::RGBA32F, 256, rows, 1, "test particles.pool");
    gpu.drawPoolView(view.name(), int(clocks.emitters().size()));
    FloatImage gpuView = gl::readTexture(view);
    std::vector<float> cpuView = cpu.poolViewTexels(rows);
    int differing = 0;
    for (int i = 0; i < 256 * rows; ++i)
        for (int c = 0; c < 4; ++c)
            differing +=
                std::abs(gpuView.texel(i % 256, i / 256, c) - cpuView[std::size_t(i * 4 + c)]) > 1e-5f;
    EXPECT_EQ(differing, 0);
    std::size_t green = 0;
    for (std::size_t i = 1; i < cpuView.size(); i += 4) green += cpuView[i] == 1.0f ? 1 : 0;
    EXPECT_EQ(green, expectedList.size());  // one green texel per live slot

    // The same run again: the same bytes.
    ParticleSystem clocks2(setups, false);
    GpuParticles gpu2(clocks2);
    for (double dt : steps) {
        clocks2.update(dt);
        renderer.setEmitters(clocks2.emitters());
        gpu2.simulate(clocks2, dt, renderer.emitterBuffer());
    }
    std::vector<GpuParticle> pool2 = gpu2.readPool();
    EXPECT_EQ(0, std::memcmp(pool.data(), pool2.data(), pool.size() * sizeof(GpuParticle)));
}

TEST_F(Particles, ZeroLiveParticlesDrawNothingWithoutError) {
    ParticleSystem clocks({setupOf(chapterFire(), false)}, false);
    renderer.setEmitters(clocks.emitters());
    GpuParticles gpu(clocks);
    Target target(32, 32, TextureFormat::RGBA16F, {0.25f, 0.5f, 0.75f, 1.0f});
    target.bind(false);
    EXPECT_EQ(renderer.drawIndirect(gpu, camera(32, 32)), 1);  // before any simulation
    clocks.update(0.0);
    gpu.simulate(clocks, 0.0, renderer.emitterBuffer());  // dt = 0: nothing spawns
    target.bind(false);
    EXPECT_EQ(renderer.drawIndirect(gpu, camera(32, 32)), 1);
    target.unbind();
    EXPECT_EQ(gpu.readStats().live, 0u);
    EXPECT_EQ(gpu.readDrawCommand()[1], 0u);
    Extremes e = extremes(target.read());
    EXPECT_EQ(e.min, 0.25f);
    EXPECT_EQ(e.max, 0.75f);
}

TEST_F(Particles, FullGpuPoolReplacesTheOldestAndDrawsTheCapacity) {
    ParticleEmitter e = chapterFire();
    e.ratePerSecond = 200.0f;
    ParticleSystem clocks({setupOf(e, false, 10)}, false);
    GpuParticles gpu(clocks);
    for (int i = 0; i < 20; ++i) {
        clocks.update(1.0 / 60.0);
        renderer.setEmitters(clocks.emitters());
        gpu.simulate(clocks, 1.0 / 60.0, renderer.emitterBuffer());
    }
    GpuParticleStats stats = gpu.readStats();
    EXPECT_EQ(stats.live, 10u);
    EXPECT_EQ(gpu.readDrawCommand()[1], 10u);  // the draw draws the capacity, no more
    EXPECT_GT(stats.replaced, 20u);
}

// --- Drawing ---

TEST_F(Particles, ChapterAlphaSubtractsAfterAHitchAndTheFixDoesNot) {
    // One particle half a second past its life: the chapter draws it with alpha -0.5.
    ParticleEmitter e = chapterFire();
    e.position = {0, 0, -4};
    ParticleSystem chapter({setupOf(e, true)});
    ParticleSystem fixed({setupOf(e, false)});
    GpuParticle p = ParticleSystem::spawnParticle(e, 0, 0, 1.5f);
    p.originAge = glm::vec4(0, -3.0f, -4, 1.5f);  // rises back to (0, 0, -4) at age 1.5
    auto drawOne = [&](const ParticleSystem& system) {
        Target target(16, 16, TextureFormat::RGBA16F, {1, 1, 1, 1});
        renderer.setEmitters(system.emitters());
        target.bind(false);
        renderer.drawObjects({p}, camera(16, 16));
        target.unbind();
        return extremes(target.read());
    };
    Extremes bug = drawOne(chapter), fix = drawOne(fixed);
    EXPECT_LT(bug.min, 0.5f) << "the chapter's negative alpha should darken the white target";
    EXPECT_GE(fix.min, 1.0f - 1e-3f);
    EXPECT_TRUE(bug.finite && fix.finite);
}

TEST_F(Particles, ParticleAtTheCameraOrNearPlaneIsFiniteAndBounded) {
    ParticleEmitter e = chapterFire();
    e.startSize = e.endSize = 100.0f;  // a huge sprite
    e.startColor = e.endColor = {1, 1, 1, 1};
    ParticleSystem system({setupOf(e, false)});
    renderer.setEmitters(system.emitters());
    const float distances[] = {0.0f, 0.05f, 0.1f, 0.11f, 1.0f};
    for (float d : distances) {
        GpuParticle p = ParticleSystem::spawnParticle(e, 0, 0, 0.0f);
        p.originAge = glm::vec4(0, 0, -d, 0.0f);
        p.velocityLife = glm::vec4(0, 0, 0, 1.0f);
        Target target(32, 32, TextureFormat::RGBA16F, {0, 0, 0, 1});
        target.bind(false);
        renderer.drawObjects({p}, camera(32, 32));
        target.unbind();
        FloatImage image = target.read();
        EXPECT_TRUE(extremes(image).finite) << "distance " << d;
        int covered = 0;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x) covered += image.texel(x, y, 0) > 0.5f ? 1 : 0;
        // Half-width at most a quarter of the distance: about half the view's height at 50 degrees.
        EXPECT_LT(covered, 32 * 32 / 2) << "distance " << d;
        if (d == 0.0f) {
            EXPECT_EQ(covered, 0);
        }
    }
}

TEST_F(Particles, AdditiveLightPastAHalfFloatStaysFinite) {
    // 40 additive layers of 60000 (clamped to 4096 each) sum to 163840 in the 32-bit off-screen
    // target; the composite clamps before the 16-bit scene target.
    ParticleEmitter e = chapterFire();
    e.startColor = e.endColor = {60000, 60000, 60000, 1};
    ParticleSystem system({setupOf(e, false)});
    renderer.setEmitters(system.emitters());
    std::vector<GpuParticle> layers;
    for (int i = 0; i < 40; ++i) {
        GpuParticle p = ParticleSystem::spawnParticle(e, 0, std::uint64_t(i), 0.0f);
        p.originAge = glm::vec4(0, 0, -2, 0);
        p.velocityLife = glm::vec4(0, 0, 0, 1);
        layers.push_back(p);
    }
    Target offscreen(16, 16, TextureFormat::RGBA32F, {0, 0, 0, 0});
    ParticleDrawSettings s = camera(16, 16);
    s.premultiplied = true;
    offscreen.bind(true);
    renderer.drawInstanced(layers, s);
    offscreen.unbind();
    Extremes sum = extremes(offscreen.read());
    EXPECT_TRUE(sum.finite);
    EXPECT_GT(sum.max, 65504.0f) << "the test should exceed a half float";

    Target scene(16, 16, TextureFormat::RGBA16F, {1, 1, 1, 1});
    FullscreenPass composite("effects/particles/particles_composite.frag", "test particles composite");
    ASSERT_TRUE(programsBuilt());
    scene.bind(true);
    glProgramUniform1f(composite.program(), glsl::kHdrMaxLocation, 4096.0f);
    composite.draw({offscreen.color.name()});
    scene.unbind();
    Extremes out = extremes(scene.read());
    EXPECT_TRUE(out.finite);
    EXPECT_LE(out.max, 4096.0f + 1.0f);
    EXPECT_GE(out.max, 4096.0f);
}

TEST_F(Particles, SoftFadeLinearisesDepthAndGuardsDistanceZero) {
    // The scene's surface is 5 m away; the particle 1 m in front of it. A 2 m soft distance fades it
    // to smoothstep(0.5) = 0.5 only if both depths are distances (a raw depth-buffer difference is tiny).
    ParticleEmitter e = chapterFire();
    e.startColor = e.endColor = {1, 1, 1, 1};
    e.startSize = e.endSize = 3.0f;
    ParticleSystem system({setupOf(e, false)});
    renderer.setEmitters(system.emitters());
    GpuParticle p = ParticleSystem::spawnParticle(e, 0, 0, 0.0f);
    p.originAge = glm::vec4(0, 0, -4, 0);
    p.velocityLife = glm::vec4(0, 0, 0, 1);

    const float near = 0.1f, far = 100.0f, surface = 5.0f;
    const float depthValue = (far * (surface - near)) / (surface * (far - near));  // GL's [0, 1] depth
    gl::Texture depth = gl::Texture::create2D(TextureFormat::Depth32F, 8, 8, 1, "test particles.scene_depth");
    std::vector<float> texels(64, depthValue);
    glTextureSubImage2D(depth.name(), 0, 0, 0, 8, 8, GL_DEPTH_COMPONENT, GL_FLOAT, texels.data());

    auto centreAlpha = [&](float soft) {
        Target target(8, 8, TextureFormat::RGBA32F, {0, 0, 0, 0});
        ParticleDrawSettings s = camera(8, 8);
        s.premultiplied = true;
        s.softDistance = soft;
        s.sceneDepth = depth.name();
        s.nearPlane = near;
        s.farPlane = far;
        target.bind(true);
        renderer.drawObjects({p}, s);
        target.unbind();
        FloatImage image = target.read();
        EXPECT_TRUE(extremes(image).finite) << "soft distance " << soft;
        return image.texel(4, 4, 0);  // premultiplied red = alpha for a white particle
    };
    const float unfaded = centreAlpha(0.0f);  // soft fade off: the sprite's own alpha
    ASSERT_GT(unfaded, 0.5f);
    EXPECT_NEAR(centreAlpha(2.0f) / unfaded, 0.5f, 0.01f);
    EXPECT_NEAR(centreAlpha(0.25f) / unfaded, 1.0f, 0.01f);  // 1 m in front, fade over 0.25 m: opaque
    // Distance 0 (or nearly): guarded, the particle stays finite and is either opaque or gone.
    float zero = centreAlpha(1e-9f);
    EXPECT_TRUE(std::isfinite(zero));
    // Behind the scene's surface: faded out completely (the depth test the fade replaces).
    p.originAge.z = -6.0f;
    EXPECT_EQ(centreAlpha(0.5f), 0.0f);
}

TEST_F(Particles, EverySourceDrawsTheSamePictureWithEveryFadeAndBlend) {
    // The same particles drawn one per draw, instanced and from the GPU's live list, with the fade off
    // and on, straight and premultiplied: each combination is its own program (#defines), and the three
    // sources must agree in each, while the fade and the blend must change the picture.
    ParticleEmitter e = chapterFire();
    e.ratePerSecond = 120.0f;
    e.spread = 0.7f;
    e.spinDegreesPerSecond = 120.0f;
    std::vector<EmitterSetup> setups = {setupOf(e, false)};
    ParticleSystem clocks(setups, false);
    GpuParticles gpu(clocks);
    ASSERT_TRUE(programsBuilt());
    for (int i = 0; i < 90; ++i) {  // 1.5 s: the oldest have died and the ring has wrapped
        clocks.update(1.0 / 60.0);
        renderer.setEmitters(clocks.emitters());
        gpu.simulate(clocks, 1.0 / 60.0, renderer.emitterBuffer());
    }
    // The GPU's live particles in the order its live list draws them, for the other two sources. The
    // list must skip free slots, or reading particles[instance] would draw the same picture.
    std::vector<GpuParticle> pool = gpu.readPool();
    std::vector<std::uint32_t> list = gpu.readLiveList();
    ASSERT_GE(list.size(), 60u);
    ASSERT_LT(list.size(), pool.size());
    ASSERT_NE(list.back(), std::uint32_t(list.size() - 1)) << "the live list should have gaps";
    std::vector<GpuParticle> live;
    for (std::uint32_t slot : list) live.push_back(pool[slot]);

    // The scene's surface 4.5 m away, the emitter at 4 m: a 1 m fade thins the particles.
    const float near = 0.1f, far = 100.0f, surface = 4.5f;
    gl::Texture depth =
        gl::Texture::create2D(TextureFormat::Depth32F, 24, 24, 1, "test particles.scene_depth");
    std::vector<float> texels(24 * 24, (far * (surface - near)) / (surface * (far - near)));
    glTextureSubImage2D(depth.name(), 0, 0, 0, 24, 24, GL_DEPTH_COMPONENT, GL_FLOAT, texels.data());

    auto sum = [](const FloatImage& image) {
        double total = 0.0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                for (int c = 0; c < 4; ++c) total += image.texel(x, y, c);
        return total;
    };
    std::set<std::string> labels;
    double totals[2][2] = {};
    for (int soft = 0; soft < 2; ++soft)
        for (int premultiplied = 0; premultiplied < 2; ++premultiplied) {
            ParticleDrawSettings s = camera(24, 24);
            s.view = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -1.0f, 0.0f));
            s.premultiplied = premultiplied == 1;
            s.softDistance = soft ? 1.0f : 0.0f;
            s.sceneDepth = depth.name();
            s.nearPlane = near;
            s.farPlane = far;
            FloatImage images[3];
            for (int source = 0; source < 3; ++source) {
                Target target(24, 24, TextureFormat::RGBA32F, {0, 0, 0, 0});
                target.bind(s.premultiplied);
                const int calls = source == 0   ? renderer.drawObjects(live, s)
                                  : source == 1 ? renderer.drawInstanced(live, s)
                                                : renderer.drawIndirect(gpu, s);
                EXPECT_EQ(calls, source == 0 ? int(live.size()) : 1);
                target.unbind();
                images[source] = target.read();
                EXPECT_TRUE(extremes(images[source], 4).finite);
            }
            const std::string variant = cat("soft ", soft, ", premultiplied ", premultiplied);
            for (int source = 1; source < 3; ++source) {
                float largest = 0.0f;
                for (int y = 0; y < 24; ++y)
                    for (int x = 0; x < 24; ++x)
                        for (int c = 0; c < 4; ++c)
                            largest = std::max(
                                largest, std::abs(images[source].texel(x, y, c) - images[0].texel(x, y, c)));
                EXPECT_LT(largest, 1e-3f) << variant << ", source " << source << " against one per draw";
            }
            totals[soft][premultiplied] = sum(images[0]);
            EXPECT_GT(totals[soft][premultiplied], 1.0) << variant << ": nothing drawn";
            for (auto source : {ParticleRenderer::Source::buffer, ParticleRenderer::Source::liveList,
                                ParticleRenderer::Source::uniforms})
                labels.insert(renderer.program(source, s).program().label());
        }
    // The fade thins both blends, and the blends differ (premultiplied fire, coverage 0, writes alpha 0).
    EXPECT_LT(totals[1][0], 0.9 * totals[0][0]);
    EXPECT_LT(totals[1][1], 0.9 * totals[0][1]);
    EXPECT_NE(totals[0][0], totals[0][1]);
    // One program per combination, each labelled with its choices.
    EXPECT_EQ(renderer.programsBuilt(), 12);
    EXPECT_EQ(labels.size(), 12u);
    EXPECT_EQ(labels.count("particles: sprites (live list, soft, premultiplied)"), 1u);
    EXPECT_EQ(labels.count("particles: sprites (one per draw, straight)"), 1u);
    EXPECT_TRUE(programsBuilt());
}

TEST_F(Particles, MissingSpriteNamesThePath) {
    Status s = renderer.loadSprite("/nonexistent/dir/particle_fire.png");
    ASSERT_FALSE(s);
    EXPECT_NE(s.error().find("/nonexistent/dir/particle_fire.png"), std::string::npos) << s.error();
}

}  // namespace
