#version 450 core
// The check of exercise 03-1: linear light from 0 to 1.5 across (0 and exact 1 included, and values
// in the curve's linear toe), even rows through a framebuffer that encodes, odd rows through one that
// does not. It writes what the screen shows: GL's encoding applied where the framebuffer does it.
#include "window_value.glsl"

layout(location = 20) uniform vec2 probeSize;

layout(location = 0) out vec4 result;

vec3 glEncodes(vec3 c) {
    c = clamp(c, 0.0, 1.0);  // an sRGB framebuffer stores [0, 1]
    vec3 curve = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
    return mix(12.92 * c, curve, step(vec3(0.0031308), c));
}

void main() {
    vec2 cell = floor(gl_FragCoord.xy);
    float x = cell.x / max(probeSize.x - 1.0, 1.0);
    vec3 light = vec3(1.5 * x, 0.004 * x, x * x);
    bool encodes = (int(cell.y) & 1) == 0;
    vec3 written = windowValue(light, encodes);
    result = vec4(encodes ? glEncodes(written) : clamp(written, 0.0, 1.0), 1.0);
}
