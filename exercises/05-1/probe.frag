#version 450 core
// The check of exercise 05-1: the tap offset v of every pixel, as the blur computes it (RG), with the
// guarded formula. The check sets the uniforms of radial_blur_offset.glsl from exercise.json.
#include "effects/post/radial_blur_offset.glsl"

layout(location = 0) out vec4 result;

void main() {
    result = vec4(tapOffset(gl_FragCoord.xy), 0.0, 1.0);
}
