#version 450 core
// The CoC as a picture: the scene in grey where it is in focus (blur radius under half a pixel), the
// near field orange and the far field blue, brighter the larger the blur, full at the clamp.
#include "coc.glsl"

layout(binding = 0) uniform sampler2D scene;
layout(binding = 1) uniform sampler2D cocTexture;

layout(location = 0) out vec4 color;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 hdr = max(texelFetch(scene, p, 0).rgb, vec3(0.0));
    float luma = dot(hdr, vec3(0.2126, 0.7152, 0.0722));
    vec3 grey = vec3(0.35 * luma / (1.0 + luma));
    float c = texelFetch(cocTexture, p, 0).r;
    float radius = blurRadiusPixels(c);
    // The full colour at the largest radius the clamp allows (guarded: a clamp of 0 shows no colour).
    float t = radius < 0.5 ? 0.0 : clamp(radius / max(blurRadiusPixels(lens.z), 1e-6), 0.15, 1.0);
    vec3 field = c < 0.0 ? vec3(1.0, 0.35, 0.02) : vec3(0.05, 0.35, 1.0);
    color = vec4(mix(grey, field, t), 1.0);
}
