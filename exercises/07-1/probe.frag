#version 450 core
// The check of exercise 07-1: every pixel is one corner of one sprite (the four corners in turn), born
// at a random angle and aged 0 to 3 s; it writes the turned corner.
#include "sprite_spin.glsl"
#include "../probe_inputs.glsl"

layout(location = 0) out vec4 result;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    int k = (pixel.x + pixel.y) & 3;
    vec2 corner = vec2(float(k & 1), float((k >> 1) & 1)) * 2.0 - 1.0;
    float angleAtBirth = 6.2831853 * probeRandom(pixel, 0u);
    float age = 3.0 * probeRandom(pixel, 1u);
    result = vec4(spunCorner(corner, angleAtBirth, age), 0.0, 1.0);
}
