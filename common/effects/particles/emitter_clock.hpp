#pragma once
// When an emitter spawns: the spawn timer of the Shader effects chapter's FireEmitter, and the fixed
// one. Both run on the CPU once per emitter per frame (no per-particle work), for every simulation
// path; what they return is a batch the CPU ring or the GPU compute pass then writes.
//
// The chapter's timer: timer += dt; if timer >= period, spawn one and timer -= period. At most one
// spawn per frame, so after a long frame the backlog bursts out one particle a frame for several
// frames (the chapter's hard case 23), all at the emitter, born at age 0.
// The fixed timer: every spawn the frame owes, each born at the moment it was due (so its age is
// already what it would have been), and none that would already be dead: a burst is bounded by
// lifetime / period + 1 particles however long the frame.
#include <cstdint>

namespace fx {

struct SpawnBatch {
    std::uint32_t count = 0;        // particles to write this frame
    std::uint64_t firstNumber = 0;  // spawn number of the oldest one (the hash's input)
    float newestAge = 0;            // age of the newest; particle k (0 = oldest) has
    float period = 0;               //   newestAge + (count - 1 - k) * period
    std::uint64_t skipped = 0;      // spawns owed but already dead at birth (fixed timer only)
};

class EmitterClock {
public:
    EmitterClock() = default;
    EmitterClock(float ratePerSecond, float lifetimeSeconds, bool chapterTimer);

    // Advances by dt seconds (NaN or negative: 0) and says what to spawn.
    SpawnBatch tick(double dt);
    double backlog() const { return timer_; }  // seconds of spawns still owed
    std::uint64_t spawned() const { return number_; }

    // The most particles one tick can spawn (the bound on a burst).
    std::uint32_t maxBurst() const;

private:
    double period_ = 0.2;
    double lifetime_ = 1.0;
    bool chapter_ = false;
    double timer_ = 0;
    std::uint64_t number_ = 0;
};

}  // namespace fx
