// The CPU particle simulation's clock (lesson 07, Shader effects §3.8 and hard case 22): dt = 0, a one
// second hitch under the chapter's rules and the fixed ones, and a full pool. No GL.
#include "test_particles_harness.hpp"

using namespace fx;
using namespace fx::test;

namespace {

TEST(ParticleClock, ZeroDtSpawnsNothingAndAgesNothing) {
    ParticleSystem system({setupOf(chapterFire(), false)});
    system.update(0.5);
    std::vector<GpuParticle> before, after;
    system.collect(before);
    ASSERT_GT(before.size(), 0u);
    system.update(0.0);
    system.collect(after);
    ASSERT_EQ(before.size(), after.size());
    for (std::size_t i = 0; i < before.size(); ++i) EXPECT_EQ(before[i].originAge.w, after[i].originAge.w);
    EXPECT_EQ(system.spawnedLastFrame(), 0u);
    // NaN and negative frames do not run the clock backwards either.
    system.update(std::nan(""));
    system.update(-1.0);
    system.collect(after);
    EXPECT_EQ(before.size(), after.size());
}

TEST(ParticleClock, OneSecondHitchFixedRulesNoNegativeAlphaAndABoundedBurst) {
    ParticleSystem system({setupOf(chapterFire(), false)});
    for (int i = 0; i < 60; ++i) system.update(1.0 / 60.0);
    system.update(1.0);  // the hitch
    // Every spawn owed in the last second, but no more than can be alive: 1 s / 0.2 s + 1.
    EXPECT_LE(system.spawnedLastFrame(), 6u);
    EXPECT_GE(system.spawnedLastFrame(), 4u);
    EXPECT_LE(system.liveCount(), 6u);
    std::vector<GpuParticle> live;
    system.collect(live);
    for (const GpuParticle& p : live) {
        EXPECT_LT(p.originAge.w, p.velocityLife.w) << "a dead particle would be drawn";
        EXPECT_GE(drawnAlpha(p, system.emitters()[0]), 0.0f);
    }
    // The frames after the hitch spawn at the steady rate: no backlog.
    std::uint64_t after = 0;
    for (int i = 0; i < 12; ++i) {
        system.update(1.0 / 60.0);
        after += system.spawnedLastFrame();
    }
    EXPECT_LE(after, 2u);
    // A very long frame (a day) is bounded the same way.
    system.update(86400.0);
    EXPECT_LE(system.spawnedLastFrame(), 6u);
    system.update(1.0e300);  // and an absurd one: no overflow converting what is owed to an integer
    EXPECT_LE(system.spawnedLastFrame(), 6u);
    EXPECT_LE(system.liveCount(), 6u);
}

TEST(ParticleClock, OneSecondHitchChapterRulesShowTheBugs) {
    ParticleSystem system({setupOf(chapterFire(), true)});
    for (int i = 0; i < 60; ++i) system.update(1.0 / 60.0);
    system.update(0.5);
    std::vector<GpuParticle> live;
    system.collect(live);
    float lowest = 1.0f;
    for (const GpuParticle& p : live) lowest = std::min(lowest, drawnAlpha(p, system.emitters()[0]));
    EXPECT_LT(lowest, -0.2f) << "the chapter draws a particle past its life with alpha below 0";
    // The backlog bursts out one particle a frame for the following frames.
    int spawningFrames = 0;
    for (int i = 0; i < 4; ++i) {
        system.update(1.0 / 60.0);
        spawningFrames += system.spawnedLastFrame() == 1 ? 1 : 0;
    }
    EXPECT_GE(spawningFrames, 2);
}

TEST(ParticleClock, FullPoolReplacesTheOldestAndCounts) {
    ParticleEmitter e = chapterFire();
    e.ratePerSecond = 100.0f;
    ParticleSystem system({setupOf(e, false, 8)});
    for (int i = 0; i < 30; ++i) system.update(1.0 / 60.0);
    EXPECT_EQ(system.liveCount(), 8u);
    EXPECT_GT(system.replacedCount(), 0u);
    // The survivors are the newest: ages below 8 spawn periods plus a frame.
    std::vector<GpuParticle> live;
    system.collect(live);
    for (const GpuParticle& p : live) EXPECT_LT(p.originAge.w, 8.0f / 100.0f + 1.0f / 60.0f);
}

}  // namespace
