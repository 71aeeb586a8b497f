#pragma once
// The particle pool on the GPU (lesson 07, step 4): compute shaders age, free and spawn particles in a
// fixed-capacity pool (shaders/effects/particles/simulate.comp), then list the live ones in a stable
// order and write the indirect draw's instance count (compact.comp), so the draw
// (ParticleRenderer::drawIndirect) draws exactly the live particles and the CPU touches none of them.
// The CPU keeps the emitter table and the spawn clocks (ParticleSystem without particles).
//
// Buffers, by their GL labels: particles.pool (48 bytes a slot), particles.live (one index a slot),
// particles.draw_command (glDrawArraysIndirect's four words) and particles.stats (replaced, live).
#include <array>
#include <cstdint>

#include "effects/particles/particle_system.hpp"
#include "gl/object.hpp"
#include "gl/program.hpp"

namespace fx {

struct GpuParticleStats {
    std::uint32_t live = 0;      // the indirect draw's instance count
    std::uint32_t replaced = 0;  // spawns that replaced the oldest live particle (pool full)
};

class GpuParticles {
public:
    // Buffers for `system`'s pool (every slot free), and the compute programs. simulate() does nothing
    // while a program has never built (the runner shows its error).
    explicit GpuParticles(const ParticleSystem& system);

    std::uint32_t capacity() const { return capacity_; }
    std::uint64_t bytes() const;

    // Runs one frame on the GPU: `system.update(dt)` on the CPU gives the spawn batches and the ring
    // heads; `emitters` is the buffer holding system.emitters() (binding 1) after that update.
    void simulate(const ParticleSystem& system, double dt, GLuint emitters) const;
    // Frees every slot and zeroes the stats (the bench starts each frame from the same state).
    void clear() const;
    // Writes the pool into `view` (RGBA32F, 256 texels a row): the inspector's particles.pool.
    void drawPoolView(GLuint view, int emitters) const;
    // Binds the pool (0), the live list (2) and the command buffer for glDrawArraysIndirect.
    void bindForDraw() const;
    // Reads the stats back (a stall: for facts and tests, not in bench frames).
    GpuParticleStats readStats() const;
    // The slots as they are now, and the live list the draw reads (tests).
    std::vector<GpuParticle> readPool() const;
    std::vector<std::uint32_t> readLiveList() const;
    // glDrawArraysIndirect's four words as the draw will read them: count, instances, first, base.
    std::array<std::uint32_t, 4> readDrawCommand() const;

private:
    bool runnable() const { return simulate_.usable() && compact_.usable(); }

    gl::ReloadableProgram simulate_{{{}, {}, "effects/particles/simulate.comp", {}, "particles: simulate"}};
    gl::ReloadableProgram compact_{{{}, {}, "effects/particles/compact.comp", {}, "particles: compact"}};
    gl::ReloadableProgram poolView_{{{}, {}, "effects/particles/pool_view.comp", {}, "particles: pool view"}};
    gl::BufferName pool_, live_, command_, stats_;
    std::uint32_t capacity_ = 0;
};

}  // namespace fx
