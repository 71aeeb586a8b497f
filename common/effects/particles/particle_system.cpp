#include "effects/particles/particle_system.hpp"

#include <algorithm>
#include <cmath>

#include <glm/trigonometric.hpp>

#include "effects/particles/particle_hash.hpp"

namespace fx {

int defaultCapacity(const ParticleEmitter& emitter) {
    double alive = double(emitter.ratePerSecond) * double(emitter.lifetimeSeconds);
    return int(std::ceil(alive * 1.25)) + 4;
}

GpuParticle ParticleSystem::spawnParticle(const ParticleEmitter& emitter, std::uint32_t emitterIndex,
                                          std::uint64_t number, float age) {
    const std::uint32_t seed = std::uint32_t(emitter.seed);
    const std::uint32_t n = std::uint32_t(number);  // the hash sees the low 32 bits, as the GPU does
    GpuParticle p;
    p.originAge = glm::vec4(emitter.position, age);
    glm::vec3 velocity(0.0f, emitter.riseSpeed, 0.0f);
    float angle = 0.0f;
    if (emitter.spread > 0.0f) {
        // The exercise's "randomise": a sideways speed, a rise between 0.5x and 1.5x, a start angle.
        velocity.x = emitter.spread * (2.0f * particleRandom(seed, n, 1) - 1.0f);
        velocity.z = emitter.spread * (2.0f * particleRandom(seed, n, 2) - 1.0f);
        velocity.y *= 0.5f + particleRandom(seed, n, 3);
        angle = 6.2831853f * particleRandom(seed, n, 0);
    }
    p.velocityLife = glm::vec4(velocity, emitter.lifetimeSeconds);
    p.extra = glm::vec4(angle, float(emitterIndex), 1.0f, 0.0f);
    return p;
}

ParticleSystem::ParticleSystem(std::vector<EmitterSetup> setups, bool cpuParticles)
    : setups_(std::move(setups)), cpu_(cpuParticles) {
    for (const EmitterSetup& s : setups_) {
        const ParticleEmitter& e = s.emitter;
        GpuEmitter g;
        g.startColor = e.startColor;
        g.endColor = e.endColor;
        g.size = glm::vec4(e.startSize * s.sizeScale, e.endSize * s.sizeScale, e.lifetimeSeconds,
                           e.kind == EmitterKind::smoke ? 1.0f : 0.0f);
        g.motion = glm::vec4(glm::radians(e.spinDegreesPerSecond), s.rules.chapterLifetime ? 1.0f : 0.0f,
                             s.textured ? 1.0f : 0.0f, 0.0f);
        std::uint32_t slots = std::uint32_t(std::max(s.capacity > 0 ? s.capacity : defaultCapacity(e), 1));
        g.ring = glm::uvec4(capacity_, slots, 0u, 0u);
        capacity_ += slots;
        table_.push_back(g);
        clocks_.emplace_back(e.ratePerSecond, e.lifetimeSeconds, s.rules.chapterTimer);
    }
    batches_.resize(setups_.size());
    if (cpu_) slots_.resize(capacity_);
}

const std::vector<SpawnBatch>& ParticleSystem::update(double dt) {
    if (!(dt > 0)) dt = 0;
    const float step = float(dt);
    spawnedLastFrame_ = 0;
    for (std::size_t e = 0; e < table_.size(); ++e) {
        GpuEmitter& g = table_[e];
        const bool chapter = setups_[e].rules.chapterLifetime;
        SpawnBatch batch = clocks_[e].tick(dt);
        const std::uint32_t first = g.ring.x, slots = g.ring.y;
        if (batch.count > slots) {
            // More spawns in one frame than the ring has slots: the oldest of them would be overwritten
            // by the newest at once, so they are dropped (counted), on every path alike.
            const std::uint32_t excess = batch.count - slots;
            dropped_ += excess;
            batch.firstNumber += excess;
            batch.count = slots;
        }
        batches_[e] = batch;
        spawnedLastFrame_ += batch.count;
        largestBurst_ = std::max<std::uint64_t>(largestBurst_, batch.count);
        // Ring position of this frame's first spawn; the ring's oldest slot after them.
        std::uint32_t head = g.ring.z;
        g.ring.z = std::uint32_t((std::uint64_t(head) + batch.count) % slots);
        if (!cpu_) continue;
        // Age every live particle (the chapter: free the ones already past their life first).
        for (std::uint32_t i = 0; i < slots; ++i) {
            GpuParticle& p = slots_[first + i];
            if (p.extra.z == 0.0f) continue;
            if (chapter) {
                if (p.originAge.w >= p.velocityLife.w)
                    p.extra.z = 0.0f;
                else
                    p.originAge.w += step;
            } else {
                p.originAge.w += step;
                if (p.originAge.w >= p.velocityLife.w) p.extra.z = 0.0f;
            }
        }
        // Spawn into the ring, oldest first; a live particle in the way is replaced and counted.
        for (std::uint32_t k = 0; k < batch.count; ++k) {
            GpuParticle& slot = slots_[first + std::uint32_t((std::uint64_t(head) + k) % slots)];
            if (slot.extra.z != 0.0f) ++replaced_;
            float age = batch.newestAge + float(batch.count - 1 - k) * batch.period;
            slot = spawnParticle(setups_[e].emitter, std::uint32_t(e), batch.firstNumber + k, age);
        }
    }
    if (cpu_) {
        live_ = 0;
        for (const GpuParticle& p : slots_) live_ += p.extra.z != 0.0f ? 1u : 0u;
    }
    return batches_;
}

void ParticleSystem::prewarm(double seconds) {
    const int frames = int(std::ceil(std::max(seconds, 0.0) * 60.0));
    for (int i = 0; i < frames; ++i) update(1.0 / 60.0);
    largestBurst_ = 0;
    replaced_ = 0;
    dropped_ = 0;
}

void ParticleSystem::collect(std::vector<GpuParticle>& out) const {
    out.clear();
    if (!cpu_) return;
    out.reserve(live_);
    for (const GpuEmitter& g : table_) {
        for (std::uint32_t i = 0; i < g.ring.y; ++i) {
            const GpuParticle& p = slots_[g.ring.x + (g.ring.z + i) % g.ring.y];
            if (p.extra.z != 0.0f) out.push_back(p);
        }
    }
}

std::vector<float> ParticleSystem::poolViewTexels(int rows) const {
    std::vector<float> texels(std::size_t(std::max(rows, 0)) * 256 * 4, 0.0f);
    const float emitterScale = table_.size() > 1 ? 1.0f / float(table_.size() - 1) : 0.0f;
    for (std::size_t i = 0; i * 4 < texels.size(); ++i) {
        float* t = &texels[i * 4];
        t[3] = 1.0f;
        if (i >= slots_.size() || slots_[i].extra.z == 0.0f) continue;
        const GpuParticle& p = slots_[i];
        t[0] = std::clamp(p.originAge.w / std::max(p.velocityLife.w, 1e-6f), 0.0f, 1.0f);
        t[1] = 1.0f;
        t[2] = p.extra.y * emitterScale;
    }
    return texels;
}

void ParticleSystem::sortBackToFront(std::vector<GpuParticle>& particles, const glm::mat4& view) {
    auto depth = [&view](const GpuParticle& p) {
        glm::vec3 position = glm::vec3(p.originAge) + glm::vec3(p.velocityLife) * p.originAge.w;
        return (view * glm::vec4(position, 1.0f)).z;  // more negative: farther
    };
    std::stable_sort(particles.begin(), particles.end(),
                     [&](const GpuParticle& a, const GpuParticle& b) { return depth(a) < depth(b); });
}

}  // namespace fx
