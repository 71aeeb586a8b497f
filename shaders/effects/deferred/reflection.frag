#version 450 core
// The mirrored scene, shaded forward with the same light as the deferred picture (sun without its
// shadow, ambient, every point light), in linear HDR. Its world-space normals are the objects' own:
// the camera was mirrored, not the objects.
#include "../../common/scene_uniforms.glsl"
#include "point_lights.glsl"

layout(binding = kBaseColorTextureBinding) uniform sampler2D baseColorTexture;
layout(location = kHdrMaxLocation) uniform float hdrMax;

layout(location = 1) in vec2 texcoord;
layout(location = 2) in vec3 worldNormal;
layout(location = 3) in vec3 worldPosition;
layout(location = 0) out vec4 color;

void main() {
    vec3 albedo = baseColor * texture(baseColorTexture, texcoord).rgb;
    float len = length(worldNormal);
    vec3 n = len > 1e-6 ? worldNormal / len : vec3(0.0);
    vec3 toEye = cameraPosition - worldPosition;
    float eyeDistance = length(toEye);
    vec3 v = eyeDistance > 1e-6 ? toEye / eyeDistance : n;
    vec3 light = albedo * (ambientLight + lightColor * max(dot(n, toLight), 0.0));
    for (int i = 0; i < pointLightCount; ++i) light += pointLightAt(i, worldPosition, n, v, albedo, 0.3, 40.0);
    color = vec4(mix(clamp(light, 0.0, hdrMax), vec3(0.0), isnan(light)), 1.0);
}
