#version 450 core
// The scene's vertices with their world position, for the lecture's per-pixel Phong targets and the
// G-buffer (effects/deferred/). The world position is interpolated in fp32 here; the G-buffer's fat
// layout stores it, the compact layout rebuilds it from depth instead.
#include "../../common/scene_uniforms.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec2 texcoord;
layout(location = 2) in vec3 normal;

layout(location = 1) out vec2 outTexcoord;
layout(location = 2) out vec3 worldNormal;
layout(location = 3) out vec3 worldPosition;

void main() {
    outTexcoord = texcoord;
    // The scenes' model matrices carry no shear, so their upper 3x3 carries normals well enough.
    worldNormal = mat3(modelMatrix) * normal;
    vec4 world = modelMatrix * vec4(position, 1.0);
    worldPosition = world.xyz;
    gl_Position = viewProjectionMatrix * world;
}
