// Skinning: the joint matrices of the object being drawn, in the shader storage buffer at binding
// kJointMatricesBinding (0)
// (std430, as in the chapter's JointDataBlock), and the blend of a vertex's four influences.
// The blend matches fx::blendJoints (common/scene/skin.hpp), which the tests use as the reference:
//  - a weight counts only if it is above 0 and its joint index is inside the buffer (an index past the
//    end would read out of bounds);
//  - the weights left are divided by their sum, so a vertex does not grow or shrink when they do not
//    add up to 1 (and w stays 1);
//  - a vertex with no weight left keeps its bind pose (the identity) instead of collapsing to the
//    origin with w = 0, which the zero matrix would give.
#include "common/scene_bindings.glsl"

layout(std430, binding = kJointMatricesBinding) readonly buffer JointDataBlock {
    mat4 jointMatrices[];
};

const float kMinTotalWeight = 1e-6;

mat4 skinMatrix(uvec4 joints, vec4 weights) {
    uint count = uint(jointMatrices.length());
    vec4 w;
    for (int i = 0; i < 4; ++i) w[i] = (weights[i] > 0.0 && joints[i] < count) ? weights[i] : 0.0;
    float total = w.x + w.y + w.z + w.w;
    if (!(total > kMinTotalWeight)) return mat4(1.0);
    w /= total;
    uvec4 j = min(joints, uvec4(count - 1u));  // count > 0 here; weight 0 entries still read in bounds
    return w.x * jointMatrices[j.x] + w.y * jointMatrices[j.y] + w.z * jointMatrices[j.z] + w.w * jointMatrices[j.w];
}

// The normal through the blended matrix's upper 3x3, normalised unless it collapsed to zero.
vec3 skinNormal(mat4 skin, vec3 normal) {
    vec3 n = mat3(skin) * normal;
    float len = length(n);
    return len > 1e-12 ? n / len : vec3(0.0);
}
