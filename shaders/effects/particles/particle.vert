#version 450 core
// A camera-facing sprite, built in view space from gl_VertexID (a 4-vertex triangle strip): the
// quad's corners are offset along the view's x and y axes, so no vector is ever normalised (a
// particle at the camera gives no NaN), and the half-width is at most a quarter of the distance to
// the camera, so a particle at the near plane cannot cover the screen (at 50 degrees, about half its
// height at most).
//
// Where the particle comes from is built into the program (ParticleRenderer builds one per source):
//   PARTICLE_SOURCE 0: particles[gl_InstanceID] (the CPU uploaded the live ones);
//   PARTICLE_SOURCE 1: particles[liveIndex[gl_InstanceID]] (the GPU compacted them);
//   PARTICLE_SOURCE 2: the particle in three uniforms (one draw per particle).
// Not a uniform and a branch: llvmpipe shades a batch of vertices as one instruction stream and runs
// both sides of a branch under a mask even when every vertex takes the same side, so every vertex
// would pay for the reads of all three sources.
#include "particle_common.glsl"

#ifndef PARTICLE_SOURCE
#error "PARTICLE_SOURCE is set by ParticleRenderer: 0 buffer, 1 live list, 2 uniforms"
#endif

#include "particles_bindings.glsl"

layout(std430, binding = kParticleEmittersBinding) readonly buffer Emitters { Emitter emitters[]; };
#if PARTICLE_SOURCE == 2
layout(location = kParticleOneOriginAgeLocation) uniform vec4 oneOriginAge;
layout(location = kParticleOneVelocityLifeLocation) uniform vec4 oneVelocityLife;
layout(location = kParticleOneExtraLocation) uniform vec4 oneExtra;
#else
layout(std430, binding = kParticlePoolBinding) readonly buffer Particles { Particle particles[]; };
#endif
#if PARTICLE_SOURCE == 1
layout(std430, binding = kParticleLiveBinding) readonly buffer LiveIndices { uint liveIndex[]; };
#endif

layout(location = kParticleViewLocation) uniform mat4 viewMatrix;
layout(location = kParticleProjectionLocation) uniform mat4 projectionMatrix;

layout(location = 0) out vec2 corner;
layout(location = 1) out vec4 color;
layout(location = 2) flat out vec3 emitterFlags;  // coverage, textured, the chapter's unclamped alpha
layout(location = 3) out float viewDistance;

void main() {
#if PARTICLE_SOURCE == 2
    Particle p = Particle(oneOriginAge, oneVelocityLife, oneExtra);
#elif PARTICLE_SOURCE == 1
    Particle p = particles[liveIndex[gl_InstanceID]];
#else
    Particle p = particles[gl_InstanceID];
#endif
    Emitter e = emitters[uint(p.extra.y)];
    ParticleLook look = particleLook(p, e);

    corner = vec2(float(gl_VertexID & 1), float((gl_VertexID >> 1) & 1)) * 2.0 - 1.0;
    color = look.color;
    emitterFlags = vec3(e.size.w, e.motion.z, e.motion.y);

    vec4 viewPosition = viewMatrix * vec4(look.position, 1.0);
    viewDistance = -viewPosition.z;
    float halfWidth = min(0.5 * look.size, 0.25 * max(viewDistance, 0.0));
    if (p.extra.z == 0.0) halfWidth = 0.0;  // a free slot: a quad of no area
    float c = cos(look.angle), s = sin(look.angle);
    vec2 offset = mat2(c, s, -s, c) * corner * halfWidth;
    gl_Position = projectionMatrix * (viewPosition + vec4(offset, 0.0, 0.0));
}
