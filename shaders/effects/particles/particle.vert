#version 450 core
// A camera-facing sprite, built in view space from gl_VertexID (a 4-vertex triangle strip): the
// quad's corners are offset along the view's x and y axes, so no vector is ever normalised (a
// particle at the camera gives no NaN), and the half-width is at most a quarter of the distance to
// the camera, so a particle at the near plane cannot cover the screen (at 50 degrees, about half its
// height at most).
#include "particle_common.glsl"

layout(std430, binding = 0) readonly buffer Particles { Particle particles[]; };
layout(std430, binding = 1) readonly buffer Emitters { Emitter emitters[]; };
layout(std430, binding = 2) readonly buffer LiveIndices { uint liveIndex[]; };

layout(location = 0) uniform mat4 viewMatrix;
layout(location = 1) uniform mat4 projectionMatrix;
// 0: particles[gl_InstanceID] (the CPU uploaded the live ones); 1: particles[liveIndex[gl_InstanceID]]
// (the GPU compacted them); 2: the particle in the three uniforms below (one draw per particle).
layout(location = 2) uniform int particleSource;
layout(location = 3) uniform vec4 oneOriginAge;
layout(location = 4) uniform vec4 oneVelocityLife;
layout(location = 5) uniform vec4 oneExtra;

layout(location = 0) out vec2 corner;
layout(location = 1) out vec4 color;
layout(location = 2) flat out vec3 emitterFlags;  // coverage, textured, the chapter's unclamped alpha
layout(location = 3) out float viewDistance;

void main() {
    Particle p;
    if (particleSource == 2) {
        p = Particle(oneOriginAge, oneVelocityLife, oneExtra);
    } else {
        uint index = particleSource == 1 ? liveIndex[gl_InstanceID] : uint(gl_InstanceID);
        p = particles[index];
    }
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
