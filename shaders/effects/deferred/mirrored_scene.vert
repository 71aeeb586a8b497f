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
// The identity: fxlab mirrors the camera. Lesson 10's mirror_objects shows the raw-GL alternative, the
// reflection here (model matrix times it, determinant -1) and the camera as it is.
layout(location = kObjectMirrorLocation) uniform mat4 objectMirror;

layout(location = 1) out vec2 outTexcoord;
layout(location = 2) out vec3 worldNormal;
layout(location = 3) out vec3 worldPosition;

void main() {
    outTexcoord = texcoord;
    mat4 model = objectMirror * modelMatrix;
    worldNormal = mat3(model) * normal;
    vec4 world = model * vec4(position, 1.0);
    worldPosition = world.xyz;
    gl_ClipDistance[0] = dot(clipPlane.xyz, world.xyz) + clipPlane.w;
    gl_Position = viewProjectionMatrix * world;
}
