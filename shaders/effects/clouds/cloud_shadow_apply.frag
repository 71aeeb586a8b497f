#version 450 core
// Darkens the scene under the clouds (effects/clouds/cloud_shadow_pass.hpp). Drawn over scene.color with
// the blend dst x src: the factor is 1 where the transmittance is 1, so a clear sky changes nothing.
// The sun's share of the light is what a cloud can take away; the sky's ambient light stays.
#include "clouds_bindings.glsl"

layout(location = 1) in vec2 uv;
layout(location = 0) out vec4 factor;

layout(binding = 0) uniform sampler2D cloudShadow;  // transmittance toward the sun, [0, 1]
layout(location = kCloudShadowSunShareLocation) uniform float sunShare;        // the part of the ground's light the sun gives, [0, 1]

void main() {
    float t = clamp(texelFetch(cloudShadow, ivec2(gl_FragCoord.xy), 0).r, 0.0, 1.0);
    factor = vec4(vec3(1.0 - sunShare * (1.0 - t)), 1.0);
}
