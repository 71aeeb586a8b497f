#version 450 core
// One pinhole render of the accumulation reference, weighted 1/samples, added to the sum (additive
// blending into an RGBA32F target).
#include "dof_bindings.glsl"

layout(binding = 0) uniform sampler2D render;
layout(location = kDofAccumulateWeightLocation) uniform float weight;

layout(location = 0) out vec4 color;

void main() {
    color = vec4(texelFetch(render, ivec2(gl_FragCoord.xy), 0).rgb * weight, weight);
}
