#version 450 core
// The list of live particles, in slot order, and the indirect draw's instance count (lesson 07,
// step 4). One work group, so the order is the same on every run: each invocation counts the live
// slots of its stretch of the pool, a prefix sum over the 256 counts gives each stretch its place,
// and each writes its indices there. (atomicAdd would be quicker on a GPU, but the order in which
// invocations win the counter differs between runs, and so would the blended picture.)
#include "particle_common.glsl"

#include "particles_bindings.glsl"

layout(local_size_x = 256) in;

layout(std430, binding = kParticlePoolBinding) readonly buffer Particles { Particle particles[]; };
layout(std430, binding = kParticleLiveBinding) writeonly buffer LiveIndices { uint liveIndex[]; };
layout(std430, binding = kParticleStatsBinding) buffer Stats { uint replaced; uint live; };
// glDrawArraysIndirect's command: count, instanceCount, first, baseInstance.
layout(std430, binding = kParticleCommandBinding) writeonly buffer DrawCommand { uint command[4]; };

layout(location = kCompactTotalSlotsLocation) uniform uint totalSlots;

shared uint stretchStart[256];

void main() {
    uint t = gl_LocalInvocationID.x;
    uint stretch = (totalSlots + 255u) / 256u;
    uint begin = min(t * stretch, totalSlots), end = min(begin + stretch, totalSlots);

    uint count = 0u;
    for (uint slot = begin; slot < end; ++slot) count += particles[slot].extra.z != 0.0 ? 1u : 0u;
    stretchStart[t] = count;
    memoryBarrierShared();
    barrier();
    if (t == 0u) {
        uint sum = 0u;
        for (uint s = 0u; s < 256u; ++s) {
            uint c = stretchStart[s];
            stretchStart[s] = sum;
            sum += c;
        }
        command[0] = 4u;  // a triangle strip of four vertices per particle
        command[1] = sum;
        command[2] = 0u;
        command[3] = 0u;
        live = sum;
    }
    memoryBarrierShared();
    barrier();
    uint next = stretchStart[t];
    for (uint slot = begin; slot < end; ++slot) {
        if (particles[slot].extra.z != 0.0) liveIndex[next++] = slot;
    }
}
