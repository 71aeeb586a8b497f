#version 450 core
// The GPU pool as a picture for the inspector (particles.pool): one texel per slot, 256 slots a row.
// Red: how far through its life (age / lifetime), green: alive, blue: which emitter (0 to 1).
#include "particle_common.glsl"

#include "particles_bindings.glsl"

layout(local_size_x = 256) in;

layout(std430, binding = kParticlePoolBinding) readonly buffer Particles { Particle particles[]; };
layout(binding = kPoolViewImageBinding, rgba32f) uniform writeonly image2D view;

layout(location = kPoolViewSlotsLocation) uniform uint slots;
layout(location = kPoolViewEmitterScaleLocation) uniform float emitterScale;  // 1 / (emitters - 1), or 0 for one emitter

void main() {
    uint slot = gl_GlobalInvocationID.x;
    ivec2 texel = ivec2(int(slot % 256u), int(slot / 256u));
    if (texel.y >= imageSize(view).y) return;
    vec4 colour = vec4(0.0, 0.0, 0.0, 1.0);
    if (slot < slots) {
        Particle p = particles[slot];
        if (p.extra.z != 0.0)
            colour = vec4(clamp(p.originAge.w / max(p.velocityLife.w, 1e-6), 0.0, 1.0), 1.0,
                          p.extra.y * emitterScale, 1.0);
    }
    imageStore(view, texel, colour);
}
