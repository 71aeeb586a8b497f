#version 450 core
// "bloom composite + output transform" (effects/bloom/bloom_composite.hpp): the composite and the
// frame's output transform in one pass. The scene and the glow are read once and the encoded colour
// written once, instead of writing bloom.result at full size and reading it back: two full-screen
// memory passes fewer. The numbers are those of upsample.frag (the composite) followed by
// effects/post/output_transform.frag, without bloom.result's rounding to a half float in between.
#include "bloom_common.glsl"
#include "../../common/output_transform.glsl"

#include "bloom_bindings.glsl"

layout(binding = 0) uniform sampler2D base;
layout(binding = 1) uniform sampler2D source;
// Chosen when the program is built (effects/post/fullscreen_variants.hpp): a uniform here would make
// llvmpipe run every filter's taps for every pixel.
const int filters = BLOOM_FILTERS;
layout(location = kBloomOffsetLocation) uniform float offset;
layout(location = kBloomUpScaleLocation) uniform float scale;
const int curve = TONE_CURVE;
layout(location = kBloomExposureLocation) uniform float exposure;

layout(location = 1) in vec2 uv;
layout(location = 0) out vec4 color;

void main() {
    vec3 under = finiteClamp(texelFetch(base, ivec2(gl_FragCoord.xy), 0).rgb, -BLOOM_MAX_VALUE, BLOOM_MAX_VALUE);
    vec3 glow = finiteClamp(upsampleFilter(source, uv, filters, offset), 0.0, BLOOM_MAX_VALUE);
    vec3 linear = finiteClamp(under + scale * glow, -BLOOM_MAX_VALUE, BLOOM_MAX_VALUE);
    color = vec4(linearToSrgb(toneCurve(linear * exposure, curve)), 1.0);
}
