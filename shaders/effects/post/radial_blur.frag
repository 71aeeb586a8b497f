#version 450 core
// Radial blur (effects/post/radial_blur.hpp): the average of taps from the pixel toward the centre.
#include "radial_blur_offset.glsl"

layout(binding = 0) uniform sampler2D source;
layout(location = kBlurSamplesLocation) uniform int samples;  // 1 to 256

layout(location = 0) out vec4 color;

void main() {
    // Input and output have the same size: the pixel's own texel, read exactly.
    vec4 here = texelFetch(source, ivec2(gl_FragCoord.xy), 0);
    // The chapter's branch: a length of 0 (or less) means no blur, and gives the input back exactly.
    if (!(blurLength > 0.0) || samples <= 1) {
        color = here;
        return;
    }
    vec2 v = tapOffset(gl_FragCoord.xy);
    // Inside the start radius every tap would land on this pixel: return it exactly.
    if (v == vec2(0.0)) {
        color = here;
        return;
    }
    // The chapter's 8 taps sit at uv + v*i, i = 0..7; other counts spread over the same 7 v.
    float spacing = 7.0 / float(samples - 1);
    vec2 uv = gl_FragCoord.xy / targetSize;
    vec3 sum = here.rgb;
    for (int i = 1; i < samples; ++i) sum += texture(source, uv + v * (float(i) * spacing)).rgb;
    // Equal weights 1/samples: they add up to 1 for every count, so a uniform image stays unchanged.
    color = vec4(sum / float(samples), here.a);
}
