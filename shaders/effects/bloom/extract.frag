#version 450 core
// The bright pass (effects/bloom/bloom_chain.hpp): keeps the part of the scene above the threshold and
// shrinks it into the chain's first level in the same pass.
//   filters 0 (Shader effects): 4 taps at +-offset texels (1: the centres of the 2x2 quads around the
//                         destination's 4x4 block), the ratio on each tap, averaged, times `scale`;
//   filters 1 (Bloom chapter): 4 diagonal taps at +-offset (0.75) averaged first, then the ratio;
//   filters 2 (reference): the texel itself, same size, no filtering.
// Every tap is made finite and non-negative first: an Inf, a NaN or a negative texel in the scene
// must not leave this pass as anything but a bounded, non-negative colour.
#include "bloom_common.glsl"

#include "bloom_bindings.glsl"

layout(binding = 0) uniform sampler2D source;
// Chosen when the program is built (effects/post/fullscreen_variants.hpp): a uniform here would make
// llvmpipe run every filter's taps for every pixel.
const int filters = BLOOM_FILTERS;
layout(location = kBloomThresholdLocation) uniform float threshold;
layout(location = kBloomKneeLocation) uniform float knee;
layout(location = kBloomScaleLocation) uniform float scale;
layout(location = kBloomOffsetLocation) uniform float offset;
const bool karis = BLOOM_KARIS != 0;

layout(location = 1) in vec2 uv;
layout(location = 0) out vec4 color;

// A half float's largest finite value: what an HDR scene can hold at most (Unity's SafeHDR).
const float kHalfMax = 65504.0;

vec3 tap(vec2 at) {
    return finiteClamp(texture(source, at).rgb, 0.0, kHalfMax);
}

void main() {
    vec3 bright;
    if (filters == 2) {
        bright = brightPart(finiteClamp(texelFetch(source, ivec2(gl_FragCoord.xy), 0).rgb, 0.0, kHalfMax),
                            threshold, knee);
    } else {
        vec2 o = offset * texelSize(source);
        vec3 t[4] = vec3[4](tap(uv + vec2(-o.x, o.y)), tap(uv + vec2(o.x, o.y)), tap(uv + vec2(-o.x, -o.y)),
                            tap(uv + vec2(o.x, -o.y)));
        if (filters == 0) {
            bright = 0.25 * (brightPart(t[0], threshold, knee) + brightPart(t[1], threshold, knee) +
                             brightPart(t[2], threshold, knee) + brightPart(t[3], threshold, knee));
        } else {
            // The Karis average weights each tap by 1 / (1 + luma): one very bright subpixel (a
            // firefly) no longer outweighs its neighbours, so it cannot flicker the whole glow as it
            // moves. The weights are renormalised, so a uniform area keeps its value.
            vec4 w = vec4(1.0);
            if (karis) w = 1.0 / (1.0 + vec4(luma(t[0]), luma(t[1]), luma(t[2]), luma(t[3])));
            vec3 mean = (w.x * t[0] + w.y * t[1] + w.z * t[2] + w.w * t[3]) / (w.x + w.y + w.z + w.w);
            bright = brightPart(mean, threshold, knee);
        }
    }
    color = vec4(finiteClamp(bright * scale, 0.0, BLOOM_MAX_BRIGHT), 1.0);
}
