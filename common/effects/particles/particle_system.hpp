#pragma once
// The particles of a scene's emitters in one fixed-capacity pool, simulated on the CPU (lesson 07's
// steps 1 to 3), and the emitter table every path shares (the GPU path keeps only the table and the
// clocks here; its particles live in GPU buffers, effects/particles/gpu_particles.hpp).
//
// Each emitter owns a ring of slots in the pool, written oldest first: when the ring is full, a new
// particle replaces the oldest live one and replacedCount() says how many did. The rules say whether
// the simulation makes the Shader effects chapter's mistakes (lesson 07, step 2) or not.
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>

#include "effects/particles/emitter_clock.hpp"
#include "effects/particles/particle_layout.hpp"
#include "scene/scene_emitter.hpp"

namespace fx {

struct ParticleRules {
    // The chapter's FireParticle: the lifespan is checked before ageing, so a particle whose life ran
    // out this frame is drawn once more with its colour extrapolated past the end (alpha below 0 after
    // a long frame). Off: aged first, freed before it is drawn, and the colour's age clamped.
    bool chapterLifetime = false;
    // The chapter's FireEmitter timer (emitter_clock.hpp). Off: every spawn owed, bounded.
    bool chapterTimer = false;
    bool operator==(const ParticleRules&) const = default;
};

struct EmitterSetup {
    ParticleEmitter emitter;
    ParticleRules rules;
    int capacity = 0;        // slots; 0: enough for rate x lifetime with a margin
    float sizeScale = 1.0f;  // multiplies the emitter's sizes (many small particles)
    bool textured = true;    // false: a soft dot instead of the sprite
    bool operator==(const EmitterSetup&) const = default;
};

// The slots an emitter needs: every particle alive at once with the fixed rules, plus a margin for
// the chapter's timer and a frame's rounding.
int defaultCapacity(const ParticleEmitter& emitter);

class ParticleSystem {
public:
    ParticleSystem() = default;
    // cpuParticles: false for the GPU path, which keeps the table and clocks only.
    explicit ParticleSystem(std::vector<EmitterSetup> setups, bool cpuParticles = true);

    // One frame: every clock ticks; on the CPU, particles age, die and spawn. Returns this frame's
    // batches, one per emitter, for the GPU path to write.
    const std::vector<SpawnBatch>& update(double dt);
    // Runs `seconds` at 60 Hz, so the first picture shows a steady flame.
    void prewarm(double seconds);

    // Every slot of the pool (CPU path; tests compare it with the GPU's).
    const std::vector<GpuParticle>& slots() const { return slots_; }
    // The pool as the inspector's picture (particles.pool, RGBA floats, 256 slots a row, `rows` rows):
    // red how far through its life, green alive, blue which emitter; as pool_view.comp on the GPU.
    std::vector<float> poolViewTexels(int rows) const;
    // Live particles, oldest first per emitter (the chapter's draw order: spawn order).
    void collect(std::vector<GpuParticle>& out) const;
    // Sorts particles back to front for `view` (farthest first; ties keep their order).
    static void sortBackToFront(std::vector<GpuParticle>& particles, const glm::mat4& view);

    const std::vector<GpuEmitter>& emitters() const { return table_; }
    const std::vector<SpawnBatch>& lastBatches() const { return batches_; }
    const std::vector<EmitterSetup>& setups() const { return setups_; }
    std::uint32_t capacity() const { return capacity_; }
    std::uint32_t liveCount() const { return live_; }
    std::uint64_t replacedCount() const { return replaced_; }
    // Spawns that never got a slot: one frame owed more than the emitter's ring holds.
    std::uint64_t droppedCount() const { return dropped_; }
    std::uint64_t spawnedLastFrame() const { return spawnedLastFrame_; }
    std::uint64_t largestBurst() const { return largestBurst_; }
    const std::vector<EmitterClock>& clocks() const { return clocks_; }

    // The particle a spawn writes: shared by the CPU ring and the GPU compute shader's twin.
    static GpuParticle spawnParticle(const ParticleEmitter& emitter, std::uint32_t emitterIndex,
                                     std::uint64_t number, float age);

private:
    std::vector<EmitterSetup> setups_;
    std::vector<GpuEmitter> table_;
    std::vector<EmitterClock> clocks_;
    std::vector<SpawnBatch> batches_;
    std::vector<GpuParticle> slots_;  // empty on the GPU path
    bool cpu_ = true;
    std::uint32_t capacity_ = 0;
    std::uint32_t live_ = 0;
    std::uint64_t replaced_ = 0;
    std::uint64_t dropped_ = 0;
    std::uint64_t spawnedLastFrame_ = 0;
    std::uint64_t largestBurst_ = 0;
};

}  // namespace fx
