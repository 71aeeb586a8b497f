#version 450 core
// The check of exercise 08-1: the opacity of one step for densities 0 to 2 across (the two scales of
// the density texture add up to 2) and step lengths from 0 to maxLength up the rows, with the lesson's
// extinction for a slab of the given thickness (0.3 x 8 / thickness, clouds.frag).
#include "cloud_step.glsl"

layout(location = 20) uniform vec2 probeSize;
layout(location = 21) uniform float maxLength;
layout(location = 22) uniform float thickness;

layout(location = 0) out vec4 result;

void main() {
    vec2 cell = floor(gl_FragCoord.xy);
    float a = 2.0 * cell.x / max(probeSize.x - 1.0, 1.0);
    float stepLength = maxLength * cell.y / max(probeSize.y - 1.0, 1.0);
    float sigmaPerDensity = 0.3 * 8.0 / thickness;
    result = vec4(stepOpacity(a, sigmaPerDensity, stepLength), 0.0, 0.0, 1.0);
}
