#version 450 core
// The CoC as a picture: the scene in grey, tinted orange in the near field and blue in the far field
// by sqrt(blur radius / the clamp's radius): sub-pixel blurs show faintly, the clamp in full colour.
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
    // Guarded: a clamp of 0 leaves every radius 0 and shows no colour.
    float t = sqrt(clamp(radius / max(blurRadiusPixels(lens.z), 1e-6), 0.0, 1.0));
    vec3 field = c < 0.0 ? vec3(1.0, 0.35, 0.02) : vec3(0.05, 0.35, 1.0);
    color = vec4(mix(grey, field, t), 1.0);
}
