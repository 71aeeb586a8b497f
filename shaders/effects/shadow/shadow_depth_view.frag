#version 450 core
// The shadow map for people: the depth written by the light's orthographic projection is already
// linear in distance, so it is turned into metres from the light's near plane (1 m = 1.0), with
// the cleared background (depth 1, nothing there) shown as -1 so it stands apart in the inspector.
#include "shadow_bindings.glsl"

layout(binding = 0) uniform sampler2D shadowDepth;
layout(location = kDepthViewRangeLocation) uniform vec2 depthRangeMetres;  // x: near, y: far, along the light
layout(location = kDepthViewTargetSizeLocation) uniform vec2 targetSize;   // the view's size in pixels
layout(location = 0) out vec4 color;

void main() {
    ivec2 size = textureSize(shadowDepth, 0);
    ivec2 at = clamp(ivec2(gl_FragCoord.xy * vec2(size) / max(targetSize, vec2(1.0))), ivec2(0), size - 1);
    float d = texelFetch(shadowDepth, at, 0).r;
    float metres = d >= 1.0 ? -1.0 : d * (depthRangeMetres.y - depthRangeMetres.x);
    color = vec4(vec3(metres), 1.0);
}
