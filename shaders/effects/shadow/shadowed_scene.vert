#version 450 core
// The lit scene with shadows (effects/shadow/shadow_lit_pass.hpp): scene_hdr.vert plus the world position,
// which the shadow lookup needs.
#include "../../common/scene_uniforms.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec2 texcoord;
layout(location = 2) in vec3 normal;

layout(location = 1) out vec2 outTexcoord;
layout(location = 2) out vec3 worldNormal;
layout(location = 3) out vec3 worldPosition;

void main() {
    outTexcoord = texcoord;
    worldNormal = mat3(modelMatrix) * normal;  // no shear in fxlab's model matrices
    vec4 world = modelMatrix * vec4(position, 1.0);
    worldPosition = world.xyz;
    gl_Position = viewProjectionMatrix * world;
}
