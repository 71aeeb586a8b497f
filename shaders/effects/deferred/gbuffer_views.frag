#version 450 core
// The G-buffer for people (the inspector and the lesson's pictures): the decoded normal as a colour
// (n * 0.5 + 0.5: +X red, +Y green, +Z blue; black where no surface or no normal) and the distance from
// the camera, linear, near white fading to black at `viewRange` metres. Two targets at once.
#include "gbuffer_read.glsl"

#include "deferred_bindings.glsl"

layout(location = kViewsEyeLocation) uniform vec3 eye;
layout(location = kViewsRangeLocation) uniform float viewRange;
layout(location = 0) out vec4 normalColour;
layout(location = 1) out vec4 linearDepth;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(depthTarget, p, 0).r;
    if (texelFetch(albedoTarget, p, 0).a < 0.5 || depth >= 1.0) {
        normalColour = vec4(0.0, 0.0, 0.0, 1.0);
        linearDepth = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    vec3 n = normalAt(p);
    normalColour = vec4(dot(n, n) > 0.0 ? n * 0.5 + 0.5 : vec3(0.0), 1.0);
    float distance = length(worldPositionAt(p, depth) - eye);
    linearDepth = vec4(vec3(1.0 - clamp(distance / max(viewRange, 1e-3), 0.0, 1.0)), 1.0);
}
