#version 450 core
// The "unlit" program of the chapter: base colour only, no light.
#include "../../common/scene_uniforms.glsl"
#include "../../common/output_transform.glsl"
out vec4 color;
void main() { color = vec4(linearToSrgb(baseColor + emissiveColor), 1.0); }
