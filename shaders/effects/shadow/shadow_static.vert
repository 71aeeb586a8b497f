#version 450 core
// Depth-only shadow pass, static meshes (Shader effects chapter §2: its shadow.vert). The light's
// view-projection is at location 2, where the lit shaders have the camera's. Only the uniforms this
// program really has are declared: a material upload to location 3 or 4 is an error here, which is
// the chapter's error flood when a draw path does not ask first (section 2.4).
#include "common/scene_bindings.glsl"

layout(location = kModelLocation) uniform mat4 modelMatrix;
layout(location = kViewProjectionLocation) uniform mat4 viewProjectionMatrix;

layout(location = 0) in vec3 position;
layout(location = 1) in vec2 texcoord;  // for the alpha cutoff (shadow_depth.frag)

layout(location = 1) out vec2 outTexcoord;

void main() {
    outTexcoord = texcoord;
    gl_Position = viewProjectionMatrix * (modelMatrix * vec4(position, 1.0));
    // Pancaking: a caster between the light and the near plane is flattened onto it instead of being
    // clipped away, so it still throws its shadow (the fit covers receivers, not every caster).
    gl_Position.z = max(gl_Position.z, -gl_Position.w);
}
