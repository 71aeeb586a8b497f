#version 450 core
// Back to full resolution: the sharp scene where the blur radius is under about a pixel, the gathered
// result (bilinear from its resolution) where it is larger, and wherever the near field's coverage
// reaches (a blurred foreground over a sharp background).
#include "coc.glsl"

layout(binding = 0) uniform sampler2D scene;
layout(binding = 1) uniform sampler2D cocTexture;
layout(binding = 2) uniform sampler2D gathered;

layout(location = 1) in vec2 uv;
layout(location = 0) out vec4 color;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 sharp = texelFetch(scene, p, 0).rgb;
    vec4 blurred = texture(gathered, uv);
    float radius = blurRadiusPixels(texelFetch(cocTexture, p, 0).r);
    float blend = max(smoothstep(0.5, 1.5, radius), blurred.a);
    color = vec4(mix(sharp, blurred.rgb, blend), 1.0);
}
