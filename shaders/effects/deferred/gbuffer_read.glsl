// Reading the G-buffer back (gbuffer.frag wrote it; LAYOUT as there): the targets on units 0 to 3,
// the world position and the normal under a pixel. The compact layout rebuilds the position from depth
// with the inverse of the view-projection the G-buffer pass drew with (the same matrices, the same size).
#include "octahedral.glsl"

#include "deferred_bindings.glsl"

layout(binding = 0) uniform sampler2D albedoTarget;
layout(binding = 1) uniform sampler2D normalTarget;
layout(binding = 2) uniform sampler2D positionTarget;  // fat layouts
layout(binding = 3) uniform sampler2D depthTarget;
layout(location = kInverseViewProjectionLocation) uniform mat4 inverseViewProjection;

vec3 worldPositionAt(ivec2 p, float depth) {
#if LAYOUT == 0
    vec2 ndc = (vec2(p) + 0.5) / vec2(textureSize(depthTarget, 0)) * 2.0 - 1.0;
    vec4 h = inverseViewProjection * vec4(ndc, depth * 2.0 - 1.0, 1.0);
    return h.xyz / (abs(h.w) > 1e-30 ? h.w : 1.0);
#else
    return texelFetch(positionTarget, p, 0).xyz;
#endif
}

vec3 normalAt(ivec2 p) {
    vec4 stored = texelFetch(normalTarget, p, 0);
#if LAYOUT == 0
    return octahedralDecode(stored.xy);
#else
    // Renormalise what the target rounded (and what a clipped RGBA8 target left of it).
    float len = length(stored.xyz);
    return len > 1e-6 ? stored.xyz / len : vec3(0.0);
#endif
}

