#version 450 core
// Lesson 03's lit scene, with the shadow of the sun. Until section 3.4 the chapter's standard.frag
// ends by encoding for the display (its pow(c, 1/2.2); here the sRGB curve the output transform
// uses), because it draws straight into the window. Once the scene goes into a float target and a
// full-screen pass encodes at the end, encoding here as well is the double-gamma washout: the fix is
// to write linear light and leave the encoding to the last pass (encodeForDisplay = 0).
#include "../../common/scene_uniforms.glsl"
#include "../../common/shadow_lookup.glsl"
#include "../../common/shadowed_lighting.glsl"
#include "../../common/output_transform.glsl"

layout(binding = kBaseColorTextureBinding) uniform sampler2D baseColorTexture;
layout(binding = kEmissiveTextureBinding) uniform sampler2D emissiveTexture;
#include "scene_lit_bindings.glsl"

layout(location = kHdrMaxLocation) uniform float hdrMax;                // effects/scene/hdr_scene_pass.hpp: kSceneHdrMax
layout(location = kEncodeForDisplayLocation) uniform int encodeForDisplay;  // 1: end with the display encoding

layout(location = 1) in vec2 texcoord;
layout(location = 2) in vec3 worldNormal;
layout(location = 3) in vec3 worldPosition;
layout(location = 0) out vec4 color;

void main() {
    vec3 albedo = baseColor * texture(baseColorTexture, texcoord).rgb;
    vec3 emitted = emissiveColor * texture(emissiveTexture, texcoord).rgb;
    vec3 linear = shadowedLighting(worldNormal, worldPosition, albedo) + emitted;
    // Finite and non-negative before anything reads it (docs/numbers.md).
    linear = mix(clamp(linear, 0.0, hdrMax), vec3(0.0), isnan(linear));
    color = vec4(encodeForDisplay != 0 ? linearToSrgb(linear) : linear, 1.0);
}
