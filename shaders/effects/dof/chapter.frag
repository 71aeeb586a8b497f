#version 450 core
// The chapter's physical depth of field: its 13 Poisson taps scaled by the centre pixel's CoC, the
// same size in pixels on both axes (a circle). Only the centre's depth decides the blur (a gather): a
// sharp foreground leaks into a blurred background's halo, and a blurred foreground stops at a hard
// edge over a sharp background (hard case 10). Taps off the screen read its edge (clamp to edge).
#include "coc.glsl"
#include "poisson.glsl"

layout(binding = 0) uniform sampler2D scene;
layout(binding = 1) uniform sampler2D cocTexture;

layout(location = 0) out vec4 color;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec2 size = vec2(textureSize(scene, 0));
    float radius = blurRadiusPixels(texelFetch(cocTexture, p, 0).r);
    vec3 sum = texelFetch(scene, p, 0).rgb;
    for (int i = 0; i < 12; ++i) sum += texture(scene, (gl_FragCoord.xy + kPoisson[i] * radius) / size).rgb;
    color = vec4(sum / 13.0, 1.0);
}
