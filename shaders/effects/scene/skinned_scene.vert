#version 450 core
// The lit scene vertex shader with skinning in it, for drawing a SkinnedMesh's source (bind pose plus
// joints and weights) directly: the chapter's skeletal path. Outputs match the plain scene vertex
// shaders (texcoord at 1, world normal at 2), so any of their fragment shaders pairs with it.
// T * (J * p): two mat4 * vec4 products instead of a mat4 * mat4 (Shader effects chapter §2).
#include "../../common/scene_uniforms.glsl"
#include "../../common/skinning.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec2 texcoord;
layout(location = 2) in vec3 normal;
layout(location = 3) in uvec4 joints;
layout(location = 4) in vec4 weights;

layout(location = 1) out vec2 outTexcoord;
layout(location = 2) out vec3 worldNormal;

void main() {
    mat4 skin = skinMatrix(joints, weights);
    outTexcoord = texcoord;
    worldNormal = mat3(modelMatrix) * skinNormal(skin, normal);
    gl_Position = viewProjectionMatrix * (modelMatrix * (skin * vec4(position, 1.0)));
}
