#version 450 core
#include "../../common/scene_uniforms.glsl"
layout(location = 0) in vec3 position;
layout(location = 1) in vec2 texcoord;
layout(location = 2) in vec3 normal;
layout(location = 1) out vec2 outTexcoord;
layout(location = 2) out vec3 worldNormal;
void main() {
    outTexcoord = texcoord;
    // The model matrix has no shear in these scenes, so its upper 3x3 carries normals well enough.
    worldNormal = mat3(modelMatrix) * normal;
    gl_Position = viewProjectionMatrix * (modelMatrix * vec4(position, 1.0));
}
