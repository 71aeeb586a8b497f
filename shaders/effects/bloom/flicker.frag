#version 450 core
// "bloom flicker" (effects/bloom/bloom_flicker.hpp): how much the glow changed since last frame, per texel,
// and a copy of this frame's glow for the next frame to compare with. The two inputs and the two
// outputs have the same size, so texel i of each is texel i of the others: no filtering.
#include "bloom_bindings.glsl"

layout(binding = 0) uniform sampler2D current;
layout(binding = 1) uniform sampler2D previous;
layout(location = kFlickerHasPreviousLocation) uniform bool hasPrevious;  // false on the first frame: no change to show

layout(location = 0) out vec4 flicker;  // bloom.flicker: |current - previous|
layout(location = 1) out vec4 history;  // bloom.history: current, kept for the next frame

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 now = texelFetch(current, p, 0).rgb;
    vec3 before = hasPrevious ? texelFetch(previous, p, 0).rgb : now;
    flicker = vec4(abs(now - before), 1.0);
    history = vec4(now, 1.0);
}
