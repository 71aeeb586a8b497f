#version 450 core
// The frame's one output transform (effects/post/output_transform_pass.hpp): linear light in, the sRGB
// encoding out. Encoding twice looks washed out and not at all looks too dark (Shader effects §3.4),
// so this is the only place that does it. With a split view the columns left of the divider show
// `before`, through the same transform, so the two halves differ only by the effect.
#include "../../common/output_transform.glsl"
#include "post_bindings.glsl"

// The split view and the tone curve are built into the program (SPLIT_VIEW, TONE_CURVE: one program
// each, effects/post/fullscreen_variants.hpp): as uniforms, llvmpipe fetched `before` and ran all three
// curves for every pixel of every frame.
layout(binding = 0) uniform sampler2D after;
#if SPLIT_VIEW
layout(binding = 1) uniform sampler2D before;
// The first pixel column that shows `after`.
layout(location = kOutputDividerLocation) uniform int divider;
#endif
// The tone curve before the encoding (effects/post/output_transform_pass.hpp: ToneCurve); 0: none.
const int curve = TONE_CURVE;
// Multiplies the light before the curve (1: unchanged).
layout(location = kOutputExposureLocation) uniform float exposure;

layout(location = 0) out vec4 color;

void main() {
    // Input and output have the same size: read the texel under the pixel, no filtering.
    ivec2 texel = ivec2(gl_FragCoord.xy);
#if SPLIT_VIEW
    bool showBefore = texel.x < divider;
    vec3 linear = showBefore ? texelFetch(before, texel, 0).rgb : texelFetch(after, texel, 0).rgb;
#else
    vec3 linear = texelFetch(after, texel, 0).rgb;
#endif
    vec3 encoded = linearToSrgb(toneCurve(linear * exposure, curve));
#if SPLIT_VIEW
    // The divider: a white column with a dark one beside it, visible on light and dark pictures.
    if (texel.x == divider) encoded = vec3(1.0);
    if (texel.x == divider - 1) encoded = vec3(0.0);
#endif
    color = vec4(encoded, 1.0);
}
