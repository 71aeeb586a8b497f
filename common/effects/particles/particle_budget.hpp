#pragma once
// How many particle slots lesson 07 may hold at once, on every path, and what a request past that
// becomes (docs/reliability.md, "Budgets").
//
// The pool grows with the scene (each emitter's rate x lifetime, up to 256 emitters) and with the
// parameters (count, pool): step 4 gives every fire emitter 100,000 particles, so 34 emitters once asked
// for a pool-view texture taller than the device allows (GL_INVALID_VALUE) and 135 for more compute
// groups than it runs. The slots asked for are checked against the device's limits and a documented
// memory budget before anything is allocated; past them, every emitter's rate and pool are scaled by
// the same factor (the flame keeps its shape with fewer, larger-spaced particles), the lesson's facts
// say so, and a warning names the emitters and the totals.
#include <cstdint>
#include <string>
#include <vector>

#include "effects/particles/particle_system.hpp"
#include "gl/device_limits.hpp"

namespace fx {

// The documented budget: at most 2^21 slots in the pool, whatever the path. 96 MiB of particles at 48
// bytes a slot; the CPU paths keep up to four copies (the pool, the draw list, the sort's copy and the
// instance buffer), 384 MiB at most.
inline constexpr std::uint64_t kParticleSlotBudget = std::uint64_t(1) << 21;
// Slots per row of the pool view (particles.pool) and per work group of the pool's compute shaders.
inline constexpr std::uint64_t kParticleSlotsPerRow = 256;

struct ParticleBudget {
    std::uint64_t asked = 0;            // slots the emitters asked for together
    std::uint64_t allowed = 0;          // the most the device and the budget allow
    std::uint64_t granted = 0;          // slots the emitters hold after fitting (at most `allowed`)
    std::string limitedBy;              // which limit sets `allowed`
    double scale = 1.0;                 // every emitter's rate and pool were multiplied by this (1: as asked)
    std::vector<std::string> emitters;  // the emitters' names (for the warning)
    // The scene's emitters behind them, when a step simulates each more than once (lesson 07's step 2
    // sets the chapter's fire beside the fixed one): the warning counts the scene's, not the copies.
    std::size_t sceneEmitters = 0;

    bool clamped() const { return asked > allowed; }
    // The facts' line: "125004 of 2097152 slots" or "4250136 slots asked; 2097152 allowed (...): x0.49".
    std::string summary() const;
    // The warning a clamp logs, naming the emitters and the totals.
    std::string warning() const;
};

// The most slots `device` can hold in one pool: the budget, the pool view's rows (GL_MAX_TEXTURE_SIZE),
// the compute groups over the pool (GL_MAX_COMPUTE_WORK_GROUP_COUNT) and the pool buffer's size
// (GL_MAX_SHADER_STORAGE_BLOCK_SIZE), whichever is least; `limitedBy` says which.
std::uint64_t particleSlotLimit(const gl::DeviceLimits& device, std::string* limitedBy = nullptr);

// Fits `setups` into the limit: unchanged when their slots fit, else every rate and pool scaled down so
// that they do (each emitter keeps at least one slot).
ParticleBudget fitParticleBudget(std::vector<EmitterSetup>& setups, const gl::DeviceLimits& device);

}  // namespace fx
