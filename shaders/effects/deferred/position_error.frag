#version 450 core
// How far the G-buffer's world position (stored, or rebuilt from depth) lies from the exact one
// (gbuffer.reference_position, RGBA32F), per pixel, as a colour on a log scale: black under 0.1 mm,
// then blue (1 mm), green (1 cm), yellow (10 cm), red (1 m and more). Alpha holds the error in metres
// (capped at a half float's 65504), so the inspector and tests can read the number.
#include "gbuffer_read.glsl"

layout(binding = 4) uniform sampler2D referencePosition;
layout(location = 0) out vec4 color;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(depthTarget, p, 0).r;
    if (texelFetch(albedoTarget, p, 0).a < 0.5 || depth >= 1.0) {
        color = vec4(0.0);
        return;
    }
    float error = length(worldPositionAt(p, depth) - texelFetch(referencePosition, p, 0).xyz);
    float t = clamp((log(max(error, 1e-5)) / log(10.0) + 4.0) / 4.0, 0.0, 1.0);  // 0.1 mm .. 1 m
    const vec3 stops[5] = vec3[](vec3(0.0), vec3(0.0, 0.2, 1.0), vec3(0.0, 0.9, 0.2), vec3(1.0, 0.9, 0.0),
                                 vec3(1.0, 0.1, 0.0));
    float x = t * 4.0;
    int i = min(int(x), 3);
    color = vec4(mix(stops[i], stops[i + 1], x - float(i)), min(error, 65504.0));
}
