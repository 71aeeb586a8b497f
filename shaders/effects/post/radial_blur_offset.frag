#version 450 core
// The radial blur's tap offset v for every pixel (RG: x and y in texture coordinates), for the
// inspector: the blur's direction and reach at a glance, and the NaN of the chapter's formula at the
// centre pixel.
#include "radial_blur_offset.glsl"

layout(location = 0) out vec2 offset;

void main() {
    // As in the blur: no length, no taps.
    offset = blurLength > 0.0 ? tapOffset(gl_FragCoord.xy) : vec2(0.0);
}
