#version 450 core
// Lights per tile as a heat map over the lit picture: black-blue-green-yellow-red-white for 0 to
// maxLights lights, mixed half and half with the picture; a tile past the list's cap is white.
#include "deferred_bindings.glsl"

layout(binding = 0) uniform sampler2D heat;  // cull.heat: one texel per tile
layout(binding = 1) uniform sampler2D lit;   // the lit picture (linear)
layout(location = kHeatMaxLightsLocation) uniform float maxLights;
layout(location = kHeatTileSizeLocation) uniform int tileSize;
layout(location = kHeatCapacityLocation) uniform float capacity;
layout(location = 0) out vec4 color;

vec3 ramp(float t) {
    const vec3 stops[5] = vec3[](vec3(0.0, 0.0, 0.3), vec3(0.0, 0.3, 1.0), vec3(0.0, 0.9, 0.2),
                                 vec3(1.0, 0.9, 0.0), vec3(1.0, 0.1, 0.0));
    float x = clamp(t, 0.0, 1.0) * 4.0;
    int i = min(int(x), 3);
    return mix(stops[i], stops[i + 1], x - float(i));
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float n = texelFetch(heat, p / max(tileSize, 1), 0).r;
    vec3 c = n > capacity ? vec3(1.0) : (n <= 0.0 ? vec3(0.0) : ramp(n / max(maxLights, 1.0)));
    // The picture through a rough tone curve so bright lights do not hide the colours.
    vec3 picture = texelFetch(lit, p, 0).rgb;
    picture = picture / (1.0 + picture);
    color = vec4(mix(picture, c, 0.6), 1.0);
}
