#version 450 core
// The list of live particles, oldest first per emitter, and the indirect draw's instance count
// (lesson 07, step 4). One work group, so the order is the same on every run: each invocation counts
// the live slots of its stretch of the pool, a prefix sum over the 256 counts gives each stretch its
// place, and each writes its indices there. (atomicAdd would be quicker on a GPU, but the order in
// which invocations win the counter differs between runs, and so would the blended picture.)
#include "particle_common.glsl"

layout(local_size_x = 256) in;

layout(std430, binding = 0) readonly buffer Particles { Particle particles[]; };
layout(std430, binding = 1) readonly buffer Emitters { Emitter emitters[]; };
layout(std430, binding = 2) writeonly buffer LiveIndices { uint liveIndex[]; };
layout(std430, binding = 3) buffer Stats { uint replaced; uint live; };
// glDrawArraysIndirect's command: count, instanceCount, first, baseInstance.
layout(std430, binding = 4) writeonly buffer DrawCommand { uint command[4]; };

layout(location = 0) uniform uint emitterCount;
layout(location = 1) uniform uint totalSlots;

shared uint stretchStart[256];

// The pool slot at place j of the pool read oldest first (each emitter's ring from its oldest slot).
uint slotAt(uint j, inout uint e) {
    while (e + 1u < emitterCount && j >= emitters[e].ring.x + emitters[e].ring.y) ++e;
    Emitter em = emitters[e];
    uint i = j - em.ring.x;
    return em.ring.x + (em.ring.z + i) % max(em.ring.y, 1u);
}

void main() {
    uint t = gl_LocalInvocationID.x;
    uint stretch = (totalSlots + 255u) / 256u;
    uint begin = min(t * stretch, totalSlots), end = min(begin + stretch, totalSlots);

    uint count = 0u, e = 0u;
    for (uint j = begin; j < end; ++j) count += particles[slotAt(j, e)].extra.z != 0.0 ? 1u : 0u;
    stretchStart[t] = count;
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
    barrier();
    uint out_ = stretchStart[t];
    e = 0u;
    for (uint j = begin; j < end; ++j) {
        uint slot = slotAt(j, e);
        if (particles[slot].extra.z != 0.0) liveIndex[out_++] = slot;
    }
}
