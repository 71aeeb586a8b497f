#version 450 core
// The check of exercise 06-1: coloured test vectors through the bright pass. The first pixels hold the
// chapter's (2, 0.5, 0), black, white at the threshold, a saturated blue and a dim grey; the rest are
// random HDR colours with channels from 0 to 4.
#include "bright_pass.glsl"
#include "../probe_inputs.glsl"

layout(location = 20) uniform float threshold;

layout(location = 0) out vec4 result;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    const vec3 firsts[5] = vec3[5](vec3(2.0, 0.5, 0.0), vec3(0.0), vec3(threshold), vec3(0.0, 0.0, 3.0), vec3(0.4));
    int index = pixel.y * 1024 + pixel.x;
    vec3 colour = index < 5 ? firsts[index]
                            : 4.0 * vec3(probeRandom(pixel, 0u), probeRandom(pixel, 1u), probeRandom(pixel, 2u));
    result = vec4(brightPass(colour, threshold), 1.0);
}
