#version 450 core
// One frame of one emitter's ring of particles on the GPU (lesson 07, step 4): every slot ages (and
// frees itself at the end of its life), then this frame's spawns are written into the ring, oldest
// first, replacing a live particle only when the ring is full (counted in stats.replaced). The CPU
// only says how many to spawn (effects/particles/emitter_clock.hpp): no per-particle work. The same
// rules and numbers as ParticleSystem::update on the CPU (common/effects/particles/particle_system.cpp).
#include "particle_common.glsl"

#include "particles_bindings.glsl"

layout(local_size_x = 256) in;

layout(std430, binding = kParticlePoolBinding) buffer Particles { Particle particles[]; };
layout(std430, binding = kParticleStatsBinding) buffer Stats { uint replaced; uint live; };

layout(location = kSimulateFirstSlotLocation) uniform uint firstSlot;
layout(location = kSimulateSlotsLocation) uniform uint slots;
layout(location = kSimulateHeadLocation) uniform uint head;  // ring index of this frame's first spawn
layout(location = kSimulateSpawnCountLocation) uniform uint spawnCount;
layout(location = kSimulateFirstNumberLocation) uniform uint firstNumber;  // low 32 bits of the oldest spawn's number
layout(location = kSimulateNewestAgeLocation) uniform float newestAge;
layout(location = kSimulatePeriodLocation) uniform float period;
layout(location = kSimulateDtLocation) uniform float dt;
layout(location = kSimulateChapterLifetimeLocation) uniform int chapterLifetime;
layout(location = kSimulateOriginLocation) uniform vec3 origin;
layout(location = kSimulateRiseSpeedLocation) uniform float riseSpeed;
layout(location = kSimulateSpreadLocation) uniform float spread;
layout(location = kSimulateSeedLocation) uniform uint seed;
layout(location = kSimulateLifetimeLocation) uniform float lifetime;
layout(location = kSimulateEmitterIndexLocation) uniform uint emitterIndex;

Particle spawnParticle(uint number, float age) {
    vec3 velocity = vec3(0.0, riseSpeed, 0.0);
    float angle = 0.0;
    if (spread > 0.0) {
        velocity.x = spread * (2.0 * particleRandom(seed, number, 1u) - 1.0);
        velocity.z = spread * (2.0 * particleRandom(seed, number, 2u) - 1.0);
        velocity.y *= 0.5 + particleRandom(seed, number, 3u);
        angle = 6.2831853 * particleRandom(seed, number, 0u);
    }
    return Particle(vec4(origin, age), vec4(velocity, lifetime), vec4(angle, float(emitterIndex), 1.0, 0.0));
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= slots) return;
    uint slot = firstSlot + i;
    Particle p = particles[slot];
    if (p.extra.z != 0.0) {
        if (chapterLifetime == 1) {
            // The chapter: a particle past its life is freed only now, after being drawn once more.
            if (p.originAge.w >= p.velocityLife.w) p.extra.z = 0.0;
            else p.originAge.w += dt;
        } else {
            p.originAge.w += dt;
            if (p.originAge.w >= p.velocityLife.w) p.extra.z = 0.0;
        }
    }
    uint k = (i + slots - head) % slots;  // this slot's place among the frame's spawns
    if (k < spawnCount) {
        if (p.extra.z != 0.0) atomicAdd(replaced, 1u);
        p = spawnParticle(firstNumber + k, newestAge + float(spawnCount - 1u - k) * period);
    }
    particles[slot] = p;
}
