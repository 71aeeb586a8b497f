#version 450 core
// The scene's vertices for the linear-HDR scene pass (effects/scene/hdr_scene_pass.hpp).
#include "../../common/scene_uniforms.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec2 texcoord;
layout(location = 2) in vec3 normal;

layout(location = 1) out vec2 outTexcoord;
layout(location = 2) out vec3 worldNormal;

void main() {
    outTexcoord = texcoord;
    // The scenes' model matrices carry no shear, so their upper 3x3 carries normals well enough.
    worldNormal = mat3(modelMatrix) * normal;
    gl_Position = viewProjectionMatrix * (modelMatrix * vec4(position, 1.0));
}
