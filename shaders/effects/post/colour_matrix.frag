#version 450 core
// Colour conversion by an affine transform on linear HDR colour (effects/post/colour_matrix.hpp):
// rgb' = colourMatrix * rgb + colourOffset. With offset 0 this is the chapter's mat3 (section 3.5);
// the offset is what an inverted picture or an added brightness needs.
#include "common/scene_bindings.glsl"
#include "post_bindings.glsl"

layout(binding = 0) uniform sampler2D source;
layout(location = kColourMatrixLocation) uniform mat3 colourMatrix;  // column-major, uploaded without transpose
layout(location = kColourOffsetLocation) uniform vec3 colourOffset;
layout(location = kHdrMaxLocation) uniform float hdrMax;             // the largest value written

layout(location = 0) out vec4 color;

void main() {
    vec4 c = texelFetch(source, ivec2(gl_FragCoord.xy), 0);
    vec3 graded = colourMatrix * c.rgb + colourOffset;
    // A matrix can push channels below zero (saturation above 1, hue rotation, -I) or far above one.
    // Negative light is meaningless to the encoding after this (the chapter's pow(c, 1/2.2) of a
    // negative value is NaN), so clamp to a finite, non-negative range.
    graded = mix(clamp(graded, 0.0, hdrMax), vec3(0.0), isnan(graded));
    color = vec4(graded, c.a);
}
