#version 450 core
// The scene's vertices for the planar reflection: lit_scene.vert's outputs, plus the clip distance to
// the mirror's plane (raised a millimetre), so that nothing below the mirror is drawn into its
// reflection (GL_CLIP_DISTANCE0 is on during the pass).
#include "../../common/scene_uniforms.glsl"

#include "deferred_bindings.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec2 texcoord;
layout(location = 2) in vec3 normal;

layout(location = kClipPlaneLocation) uniform vec4 clipPlane;  // n.p + d >= 0 is kept

layout(location = 1) out vec2 outTexcoord;
layout(location = 2) out vec3 worldNormal;
layout(location = 3) out vec3 worldPosition;

void main() {
    outTexcoord = texcoord;
    worldNormal = mat3(modelMatrix) * normal;
    vec4 world = modelMatrix * vec4(position, 1.0);
    worldPosition = world.xyz;
    gl_ClipDistance[0] = dot(clipPlane.xyz, world.xyz) + clipPlane.w;
    gl_Position = viewProjectionMatrix * world;
}
