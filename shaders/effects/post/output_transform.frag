#version 450 core
// The frame's one output transform (effects/output_transform_pass.hpp): linear light in, the sRGB
// encoding out. Encoding twice looks washed out and not at all looks too dark (Shader effects §3.4),
// so this is the only place that does it. With a split view the columns left of the divider show
// `before`, through the same transform, so the two halves differ only by the effect.
#include "../../common/output_transform.glsl"

layout(binding = 0) uniform sampler2D after;
layout(binding = 1) uniform sampler2D before;
// The first pixel column that shows `after`; -1 without a split view.
layout(location = 0) uniform int divider;
// The tone curve before the encoding (effects/output_transform_pass.hpp: ToneCurve); 0: none.
layout(location = 1) uniform int curve;
// Multiplies the light before the curve (1: unchanged).
layout(location = 2) uniform float exposure;

layout(location = 0) out vec4 color;

void main() {
    // Input and output have the same size: read the texel under the pixel, no filtering.
    ivec2 texel = ivec2(gl_FragCoord.xy);
    bool showBefore = texel.x < divider;
    vec3 linear = showBefore ? texelFetch(before, texel, 0).rgb : texelFetch(after, texel, 0).rgb;
    vec3 encoded = linearToSrgb(toneCurve(linear * exposure, curve));
    // The divider: a white column with a dark one beside it, visible on light and dark pictures.
    if (divider >= 0 && texel.x == divider) encoded = vec3(1.0);
    if (divider >= 0 && texel.x == divider - 1) encoded = vec3(0.0);
    color = vec4(encoded, 1.0);
}
