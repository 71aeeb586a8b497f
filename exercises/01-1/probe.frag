#version 450 core
// The check of exercise 01-1: every pixel is one vertex with its own four joints (a rotation and a
// translation each), weights that sum to 1 and a model matrix; it writes the vertex in the world.
#include "skinned_position.glsl"
#include "../probe_inputs.glsl"

layout(location = 0) out vec4 result;

// A rotation about a random axis by a random angle, then a translation up to `reach` metres.
mat4 randomRigid(ivec2 pixel, uint base, float reach) {
    vec3 axis = probeDirection(pixel, base);
    float angle = 6.2831853 * probeRandom(pixel, base + 3u);
    float c = cos(angle), s = sin(angle), t = 1.0 - c;
    vec3 a = axis;
    mat4 m = mat4(t * a.x * a.x + c, t * a.x * a.y + s * a.z, t * a.x * a.z - s * a.y, 0.0,
                  t * a.x * a.y - s * a.z, t * a.y * a.y + c, t * a.y * a.z + s * a.x, 0.0,
                  t * a.x * a.z + s * a.y, t * a.y * a.z - s * a.x, t * a.z * a.z + c, 0.0,
                  0.0, 0.0, 0.0, 1.0);
    m[3].xyz = reach * (probeDirection(pixel, base + 4u) * probeRandom(pixel, base + 7u));
    return m;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    mat4 joints[4];
    for (int j = 0; j < 4; ++j) joints[j] = randomRigid(pixel, uint(j) * 10u, 1.0);
    vec4 w = vec4(probeRandom(pixel, 40u), probeRandom(pixel, 41u), probeRandom(pixel, 42u), probeRandom(pixel, 43u));
    w /= max(w.x + w.y + w.z + w.w, 1e-6);
    mat4 model = randomRigid(pixel, 50u, 5.0);
    vec3 position = 2.0 * vec3(probeRandom(pixel, 60u), probeRandom(pixel, 61u), probeRandom(pixel, 62u)) - 1.0;
    result = skinnedWorld(model, blendJoints(joints, w), position);
}
