#version 450 core
// One step up the chain, and the composite (effects/bloom/bloom_chain.hpp, bloom_composite.hpp): the target
// gets `base` (same size, read texel for texel) plus `scale` times the smaller `source`, blurred while
// it is enlarged. The chapters add the enlarged level with additive blending onto the level itself;
// writing the sum into a texture of its own gives the same numbers and keeps the level as it was
// before, so the inspector can show both chains.
//   filters 0 (Shader effects): centre x3, 4 diagonals at +-offset (1) texels x2, 4 axial at 2 offset x1, / 15;
//   filters 1 (Bloom chapter): 4 axial taps at 2 offset (2 x 0.5) x1, 4 diagonal at offset x2, / 12;
//   filters 2 (reference, or a glow already blurred at its own size): one bilinear tap.
// `wide` (the top level, when the composite takes a single tap): the level itself is blurred as much as
// the composite's filter would blur it (ownBlur: four taps of the same variance) and the level below is
// enlarged with a filter widened to match (kWideUpsampleScale), so
// the blur the composite did at full size is done here at half size (effects/bloom/bloom_chain.hpp).
// Every sum is clamped below BLOOM_MAX_VALUE: levels that are finite alone cannot overflow a half
// float once they are added up (Bloom chapter, hard case 2).
#include "bloom_common.glsl"

#include "bloom_bindings.glsl"

layout(binding = 0) uniform sampler2D base;
layout(binding = 1) uniform sampler2D source;
// Chosen when the program is built (effects/post/fullscreen_variants.hpp): a uniform here would make
// llvmpipe run every filter's taps for every pixel.
const int filters = BLOOM_FILTERS;
layout(location = kBloomOffsetLocation) uniform float offset;
layout(location = kBloomUpScaleLocation) uniform float scale;
const bool wide = BLOOM_WIDE != 0;

layout(location = 1) in vec2 uv;
layout(location = 0) out vec4 color;

void main() {
    vec3 up = upsampleFilter(source, uv, filters, wide ? offset * kWideUpsampleScale : offset);
    // The scene under the glow keeps its sign (a negative texel stays as the scene made it); the glow
    // itself is never negative.
    vec3 own = wide ? ownBlur(base, uv, filters, offset) : texelFetch(base, ivec2(gl_FragCoord.xy), 0).rgb;
    vec3 under = finiteClamp(own, -BLOOM_MAX_VALUE, BLOOM_MAX_VALUE);
    vec3 glow = finiteClamp(up, 0.0, BLOOM_MAX_VALUE);
    color = vec4(finiteClamp(under + scale * glow, -BLOOM_MAX_VALUE, BLOOM_MAX_VALUE), 1.0);
}
