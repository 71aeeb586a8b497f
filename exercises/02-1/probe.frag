#version 450 core
// The check of exercise 02-1: the shadow map of a lattice seen from the light. Each pixel is a
// texel of the lattice's texture (4 cells across, bars 0.3 of a cell wide with soft edges whose alpha
// takes every eighth from 0 to 1, so some equal the cutoff exactly) in a random colour; it writes the
// depth the map keeps: the caster's 0.3 where the fragment casts, the clear value 1 where it is dropped.
#include "shadow_cutout.glsl"
#include "../probe_inputs.glsl"

layout(location = 20) uniform vec2 probeSize;
layout(location = 21) uniform float alphaCutoff;

layout(location = 0) out vec4 result;

float latticeAlpha(vec2 uv) {
    vec2 cell = fract(uv * 4.0);
    vec2 fromBar = abs(cell - 0.5);                // 0.5 at a bar's middle, 0 at a hole's middle
    float bar = max(fromBar.x, fromBar.y);
    float alpha = clamp((bar - 0.3) / 0.1, 0.0, 1.0);  // a soft edge 0.1 of a cell wide
    return floor(alpha * 8.0 + 0.5) / 8.0;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec2 uv = gl_FragCoord.xy / probeSize;
    vec4 baseColor = vec4(probeRandom(pixel, 0u), probeRandom(pixel, 1u), probeRandom(pixel, 2u), latticeAlpha(uv));
    float depth = castsShadow(baseColor, alphaCutoff) ? 0.3 : 1.0;
    result = vec4(depth, baseColor.a, 0.0, 1.0);
}
