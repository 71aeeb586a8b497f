#version 450 core
// Linear-HDR lighting with the directional light's shadow (shaders/common/shadowed_lighting.glsl).
// Written clamped and NaN-free like the plain scene pass (effects/scene/hdr_scene_pass.hpp, kSceneHdrMax).
// It can end by encoding for the display, as the chapter's standard.frag does (its pow(c, 1/2.2); here
// the sRGB curve the output transform uses): right when it draws straight into the window, the
// double-gamma washout once a full-screen pass encodes again (the FBO pipeline lesson shows both).
#include "../../common/output_transform.glsl"
#include "../../common/scene_uniforms.glsl"
#include "../../common/shadow_lookup.glsl"
#include "../../common/shadowed_lighting.glsl"
#include "shadow_bindings.glsl"

layout(binding = kBaseColorTextureBinding) uniform sampler2D baseColorTexture;
layout(binding = kEmissiveTextureBinding) uniform sampler2D emissiveTexture;
layout(location = kHdrMaxLocation) uniform float hdrMax;
layout(location = kEncodeForDisplayLocation) uniform int encodeForDisplay;  // 1: end with the display encoding
// Cut-out materials: the same cutoff the shadow pass uses (ShadowMap, kAlphaCutoff), so a surface has
// holes exactly where its shadow has them. Opaque textures (alpha 1) never reach it.
const float kAlphaCutoff = 0.5;

layout(location = 1) in vec2 texcoord;
layout(location = 2) in vec3 worldNormal;
layout(location = 3) in vec3 worldPosition;
layout(location = 0) out vec4 color;

void main() {
    vec4 base = texture(baseColorTexture, texcoord);
    if (base.a < kAlphaCutoff) discard;
    vec3 albedo = baseColor * base.rgb;
    vec3 emitted = emissiveColor * texture(emissiveTexture, texcoord).rgb;
    vec3 linear = shadowedLighting(worldNormal, worldPosition, albedo) + emitted;
    linear = mix(clamp(linear, 0.0, hdrMax), vec3(0.0), isnan(linear));
    color = vec4(encodeForDisplay != 0 ? linearToSrgb(linear) : linear, 1.0);
}
