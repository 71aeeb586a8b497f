#version 450 core
// The shadow pass writes depth only; no colour attachment exists. Like the chapter's shadow.frag it
// discards fragments whose base colour alpha is below the cutoff, so a cut-out texture (leaves, a
// fence, a lattice) casts its holes. The cutoff is a uniform of each program that links this file: a
// program whose cutoff was never set keeps GL's initial 0, discards nothing, and its cut-out casters
// throw solid shadows (Shader effects §2: the skinned shadow program needs its own cutoff).
#include "common/scene_bindings.glsl"
#include "shadow_bindings.glsl"

layout(location = kAlphaCutoffLocation) uniform float alphaCutoff;
layout(binding = kBaseColorTextureBinding) uniform sampler2D baseColorTexture;

layout(location = 1) in vec2 texcoord;

void main() {
    if (texture(baseColorTexture, texcoord).a < alphaCutoff) discard;
}
