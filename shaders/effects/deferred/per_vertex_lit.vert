#version 450 core
// Gouraud: the light at each vertex (effects/deferred/per_vertex_lighting.hpp), split into what the
// albedo multiplies (ambient, the sun's and the point lights' diffuse) and what it does not (their
// specular), interpolated to the pixels. pointLightAt is affine in the albedo, so the split is its
// value at albedo 0 (the specular) and the difference to albedo 1 (the diffuse).
// The point lights' storage buffer is read in the vertex stage here (GL 4.5 may have none there; every
// desktop driver fxlab runs on has them).
#include "../../common/scene_uniforms.glsl"
#include "point_lights.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec2 texcoord;
layout(location = 2) in vec3 normal;

layout(location = 1) out vec2 outTexcoord;
layout(location = 2) out vec3 diffuseLight;
layout(location = 3) out vec3 specularLight;

void main() {
    outTexcoord = texcoord;
    vec4 world = modelMatrix * vec4(position, 1.0);
    vec3 n = mat3(modelMatrix) * normal;
    float len = length(n);
    n = len > 1e-6 ? n / len : vec3(0.0);
    vec3 toEye = cameraPosition - world.xyz;
    float eyeDistance = length(toEye);
    vec3 v = eyeDistance > 1e-6 ? toEye / eyeDistance : n;
    diffuseLight = ambientLight + lightColor * max(dot(n, toLight), 0.0);
    specularLight = vec3(0.0);
    for (int i = 0; i < pointLightCount; ++i) {
        vec3 specular = pointLightAt(i, world.xyz, n, v, vec3(0.0), 0.3, 40.0);
        diffuseLight += pointLightAt(i, world.xyz, n, v, vec3(1.0), 0.3, 40.0) - specular;
        specularLight += specular;
    }
    gl_Position = viewProjectionMatrix * world;
}
