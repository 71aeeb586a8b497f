// Lesson 07's particle budget at its boundary: a pool that fits is left as asked, one slot more is scaled
// down to fit, and each device limit can be the one that decides (docs/reliability.md, "Budgets").
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "effects/particles/particle_budget.hpp"

namespace {

// An emitter whose pool is exactly `slots` (an explicit pool, as the `pool` parameter gives).
fx::EmitterSetup emitter(const std::string& name, int slots, float rate = 100.0f) {
    fx::EmitterSetup s;
    s.emitter.name = name;
    s.emitter.ratePerSecond = rate;
    s.capacity = slots;
    return s;
}

std::uint64_t totalSlots(const std::vector<fx::EmitterSetup>& setups) {
    std::uint64_t total = 0;
    for (const auto& s : setups) total += std::uint64_t(s.capacity);
    return total;
}

// What llvmpipe reports (Mesa 22): 16384, 65535, 128 MiB.
fx::gl::DeviceLimits llvmpipe() {
    return {16384, 65535, std::int64_t(1) << 27};
}

}  // namespace

TEST(ParticleBudget, APoolExactlyAtTheLimitIsLeftAsAsked) {
    const auto limit = fx::particleSlotLimit(llvmpipe());
    ASSERT_EQ(limit, fx::kParticleSlotBudget);
    std::vector<fx::EmitterSetup> setups = {emitter("a", int(limit / 2)),
                                            emitter("b", int(limit - limit / 2))};
    const auto before = setups;
    fx::ParticleBudget budget = fx::fitParticleBudget(setups, llvmpipe());
    EXPECT_FALSE(budget.clamped());
    EXPECT_EQ(budget.asked, limit);
    EXPECT_EQ(budget.granted, limit);
    EXPECT_EQ(setups, before);
    EXPECT_EQ(budget.summary(), "2097152 of 2097152 slots");
}

TEST(ParticleBudget, OneSlotMoreScalesEveryEmitterToFit) {
    const auto limit = fx::particleSlotLimit(llvmpipe());
    std::vector<fx::EmitterSetup> setups = {emitter("a", int(limit / 2), 200.0f),
                                            emitter("b", int(limit - limit / 2) + 1, 100.0f)};
    fx::ParticleBudget budget = fx::fitParticleBudget(setups, llvmpipe());
    EXPECT_TRUE(budget.clamped());
    EXPECT_EQ(budget.asked, limit + 1);
    EXPECT_LE(totalSlots(setups), limit);
    EXPECT_EQ(budget.granted, totalSlots(setups));
    EXPECT_LT(setups[0].emitter.ratePerSecond, 200.0f);
    EXPECT_NEAR(setups[0].emitter.ratePerSecond / setups[1].emitter.ratePerSecond, 2.0f, 1e-4f);
    EXPECT_NE(budget.summary().find("2097153 slots asked; 2097152 allowed (the particle memory budget)"),
              std::string::npos)
        << budget.summary();
}

TEST(ParticleBudget, TheIssuesEmittersAreNamedWithTheTotals) {
    // Step 4: 100,000 particles each, 125,004 slots; 256 copies asked for 32 million slots.
    std::vector<fx::EmitterSetup> setups;
    for (int i = 0; i < 256; ++i) setups.push_back(emitter("fire " + std::to_string(i), 125004));
    fx::ParticleBudget budget = fx::fitParticleBudget(setups, llvmpipe());
    EXPECT_EQ(budget.asked, 256u * 125004u);
    EXPECT_LE(totalSlots(setups), fx::kParticleSlotBudget);
    for (const auto& s : setups) EXPECT_GE(s.capacity, 1);
    const std::string warning = budget.warning();
    EXPECT_NE(
        warning.find("256 emitters ('fire 0', 'fire 1', 'fire 2', 'fire 3' and 252 more) ask for 32001024 "
                     "particle slots together; 2097152 fit (the particle memory budget"),
        std::string::npos)
        << warning;
}

TEST(ParticleBudget, EachDeviceLimitCanDecide) {
    std::string why;
    // 8 rows of 256 slots in the pool view.
    EXPECT_EQ(fx::particleSlotLimit({8, 65535, std::int64_t(1) << 30}, &why), 8u * 256u);
    EXPECT_NE(why.find("GL_MAX_TEXTURE_SIZE"), std::string::npos) << why;
    EXPECT_EQ(fx::particleSlotLimit({16384, 4, std::int64_t(1) << 30}, &why), 4u * 256u);
    EXPECT_NE(why.find("GL_MAX_COMPUTE_WORK_GROUP_COUNT"), std::string::npos) << why;
    EXPECT_EQ(fx::particleSlotLimit({16384, 65535, 48 * 1000}, &why), 1000u);
    EXPECT_NE(why.find("GL_MAX_SHADER_STORAGE_BLOCK_SIZE"), std::string::npos) << why;
    // At the storage limit exactly: kept; one more: fitted to it.
    const fx::gl::DeviceLimits small{16384, 65535, 48 * 1000};
    std::vector<fx::EmitterSetup> fits = {emitter("a", 1000)};
    EXPECT_FALSE(fx::fitParticleBudget(fits, small).clamped());
    std::vector<fx::EmitterSetup> over = {emitter("a", 1001)};
    EXPECT_TRUE(fx::fitParticleBudget(over, small).clamped());
    EXPECT_LE(over[0].capacity, 1000);
}

// Issue 40, defect 10: lesson 07's step 2 simulates each emitter twice (the chapter's fire beside the
// fixed one), and the warning counted 512 emitters for a scene of 256.
TEST(ParticleBudget, TheWarningCountsTheScenesEmittersNotTheirCopies) {
    std::vector<fx::EmitterSetup> setups;
    for (int i = 0; i < 512; ++i) setups.push_back(emitter("fire " + std::to_string(i / 2), 125004));
    fx::ParticleBudget budget = fx::fitParticleBudget(setups, llvmpipe());
    budget.sceneEmitters = 256;
    const std::string warning = budget.warning();
    EXPECT_EQ(
        warning.rfind("256 emitters of the scene, simulated as 512 ('fire 0', 'fire 0', 'fire 1', 'fire 1' "
                      "and 508 more), ask for 64002048 particle slots together",
                      0),
        0u)
        << warning;
}
