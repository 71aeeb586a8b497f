#version 450 core
// Scatter-as-you-gather with a disk kernel of rings (Unity PPv2's 16/22/43/71 taps, after Jimenez
// 2014). The kernel's radius is the largest blur radius that can reach this texel: the tile maxima
// around it. A tap at distance r from the centre counts if its own blur radius reaches back (a 1-pixel
// ramp). With near/far separation (the fields relative to the centre, as Jimenez's presort):
//   in front  a near-field tap nearer than the centre counts wherever its blur reaches: a blurred
//             foreground spreads over a sharp background, mixed over the rest by its coverage;
//   the rest  a tap counts only up to min(its radius, the centre's): a sharp foreground is not covered
//             by the background behind it; behind a near centre, within the centre's radius (what shows
//             through the near field's blurred edge).
// Without separation every tap counts up to its own radius, as a single average.
// Taps are fetched at whole texels clamped to the screen: no wrap-around from the opposite edge.
#include "dof_bindings.glsl"

layout(binding = 0) uniform sampler2D prefiltered;  // rgb, a = signed radius in gather pixels
layout(binding = 1) uniform sampler2D tileMax;
layout(location = kDofRingsLocation) uniform int rings;         // rings around the centre tap
layout(location = kDofTapsPerRingLocation) uniform int tapsPerRing;   // ring k holds tapsPerRing * k taps
// DOF_SEPARATE, near/far separation on (1) or off (0), is a #define, one program each
// (effects/post/fullscreen_variants.hpp): llvmpipe runs both sides of a branch on a uniform, so one
// field cost as much as two.
layout(location = kDofGatherTilePixelsLocation) uniform int tilePixels;
layout(location = kDofMaxRadiusLocation) uniform float maxRadius;   // gather pixels: the clamp, which bounds the tile reach
layout(location = kDofHighlightLocation) uniform float highlight;   // bokeh: extra weight per unit of luminance above 1
layout(location = kDofGatherScaleLocation) uniform int scale;         // full-resolution pixels per gather texel

layout(location = 0) out vec4 color;

const float kPi = 3.14159265;

float weightOf(vec3 rgb) {
    float luma = dot(rgb, vec3(0.2126, 0.7152, 0.0722));
    return 1.0 + highlight * max(luma - 1.0, 0.0);
}

void main() {
    ivec2 size = textureSize(prefiltered, 0);
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 centre = texelFetch(prefiltered, p, 0);

    // The kernel's reach: the tiles whose blur can arrive here (a neighbourhood as wide as the clamp).
    ivec2 tiles = textureSize(tileMax, 0);
    ivec2 t = min(p / tilePixels, tiles - 1);
    int reach = int(ceil(maxRadius / float(tilePixels)));
    float radius = abs(centre.a);
    for (int y = -reach; y <= reach; ++y)
        for (int x = -reach; x <= reach; ++x)
            radius = max(radius, texelFetch(tileMax, clamp(t + ivec2(x, y), ivec2(0), tiles - 1), 0).g);
    radius = min(radius, maxRadius);
    if (radius < 0.5) {
        color = vec4(centre.rgb, 0.0);
        return;
    }

    vec4 far = vec4(0.0), near = vec4(0.0), all = vec4(0.0);
    float nearCoverage = 0.0;
    int taps = 0;
    for (int k = 0; k <= rings; ++k) {
        int n = k == 0 ? 1 : tapsPerRing * k;
        float r = radius * float(k) / float(max(rings, 1));
        for (int i = 0; i < n; ++i) {
            float angle = 2.0 * kPi * (float(i) + 0.5 * float(k & 1)) / float(n);
            vec2 offset = r * vec2(cos(angle), sin(angle));
            ivec2 q = clamp(ivec2(floor(vec2(p) + 0.5 + offset)), ivec2(0), size - 1);
            vec4 s = texelFetch(prefiltered, q, 0);
            float w = weightOf(s.rgb);
            ++taps;
#if DOF_SEPARATE
            // In front: a near-field tap nearer than the centre by more than half a texel of blur.
            bool inFront = s.a < min(centre.a, 0.0) - 0.5;
            if (inFront) {
                float nw = clamp(-s.a - r + 1.0, 0.0, 1.0);
                near += vec4(s.rgb, 1.0) * nw * w;
                // Each tap stands for radius^2 / taps of area; a near tap's light spreads over its
                // own blur disk (s.a^2), so a uniform near field in front gives a coverage of 1.
                nearCoverage += nw * radius * radius / max(s.a * s.a, 1.0);
            } else {
                // Behind a near centre, what shows through its blurred edge: the taps not in front,
                // within the centre's radius. Behind any other centre, a tap counts only up to the
                // smaller blur of the two: a sharp foreground is not covered by the background.
                float farRadius = centre.a < -0.5 ? -centre.a : max(min(centre.a, s.a), 0.0);
                float fw = clamp(farRadius - r + 1.0, 0.0, 1.0);
                far += vec4(s.rgb, 1.0) * fw * w;
            }
#else
            float aw = clamp(abs(s.a) - r + 1.0, 0.0, 1.0);  // 1 for the centre tap
            all += vec4(s.rgb, 1.0) * aw * w;
#endif
        }
    }
#if !DOF_SEPARATE
    color = vec4(all.rgb / max(all.a, 1e-6), 0.0);
#else
    vec3 farColour = far.a > 0.0 ? far.rgb / far.a : centre.rgb;
    vec3 nearColour = near.a > 0.0 ? near.rgb / near.a : farColour;
    float alpha = near.a > 0.0 ? clamp(nearCoverage / float(taps), 0.0, 1.0) : 0.0;
    // The composite mixes this over the sharp scene by max(the pixel's own blur, alpha). Over a sharp
    // pixel the far field is the sharp scene itself, so there the near colour alone is written (the
    // composite's alpha puts it over); over a blurred one, the far and near fields mixed.
    float defocus = smoothstep(0.5, 1.5, abs(centre.a) * float(scale));
    color = vec4(mix(nearColour, mix(farColour, nearColour, alpha), defocus), alpha);
#endif
}
