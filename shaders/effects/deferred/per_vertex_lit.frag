#version 450 core
// The interpolated vertex light times the pixel's base colour (per_vertex_lit.vert), in linear HDR.
#include "../../common/scene_uniforms.glsl"

layout(binding = kBaseColorTextureBinding) uniform sampler2D baseColorTexture;
layout(location = kHdrMaxLocation) uniform float hdrMax;

layout(location = 1) in vec2 texcoord;
layout(location = 2) in vec3 diffuseLight;
layout(location = 3) in vec3 specularLight;
layout(location = 0) out vec4 color;

void main() {
    vec3 albedo = baseColor * texture(baseColorTexture, texcoord).rgb;
    vec3 light = albedo * diffuseLight + specularLight;
    color = vec4(mix(clamp(light, 0.0, hdrMax), vec3(0.0), isnan(light)), 1.0);
}
