#include "effects/particles/emitter_clock.hpp"

#include <algorithm>
#include <cmath>

namespace fx {

EmitterClock::EmitterClock(float ratePerSecond, float lifetimeSeconds, bool chapterTimer)
    : period_(1.0 / std::max(double(ratePerSecond), 1e-6)),
      lifetime_(std::max(double(lifetimeSeconds), 1e-6)),
      chapter_(chapterTimer) {}

std::uint32_t EmitterClock::maxBurst() const {
    if (chapter_) return 1;
    return std::uint32_t(std::floor(lifetime_ / period_)) + 1;
}

SpawnBatch EmitterClock::tick(double dt) {
    if (!(dt > 0)) dt = 0;     // NaN and negative frames do not run the clock backwards
    dt = std::min(dt, 1.0e9);  // a frame longer than 30 years counts as 30 years (owed stays an integer)
    SpawnBatch batch;
    batch.period = float(period_);
    timer_ += dt;
    if (chapter_) {
        if (timer_ >= period_) {
            timer_ -= period_;
            batch.count = 1;
            batch.firstNumber = number_++;
        }
        return batch;
    }
    // Spawns owed; the newest was due `timer_` seconds ago after taking them out.
    double owed = std::floor(timer_ / period_);
    timer_ -= owed * period_;
    timer_ = std::clamp(timer_, 0.0, period_);
    double alive = std::min(owed, double(maxBurst()));
    // Of the owed spawns, the newest `alive` ones; drop those already past their lifetime. The age is
    // computed in float as the spawn will compute it, so none is born at exactly its lifetime.
    const float newest = float(timer_), period = float(period_), lifetime = float(lifetime_);
    std::uint32_t count = 0;
    for (std::uint32_t k = 0; k < std::uint32_t(alive); ++k) {
        if (newest + float(k) * period < lifetime) count = k + 1;
    }
    std::uint64_t total = std::uint64_t(owed);
    batch.count = count;
    batch.skipped = total - count;
    batch.firstNumber = number_ + batch.skipped;
    batch.newestAge = newest;
    number_ += total;
    return batch;
}

}  // namespace fx
