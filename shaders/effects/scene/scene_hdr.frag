#version 450 core
// The lit scene in linear HDR (Shader effects chapter §3.4). There is no gamma here on purpose: the frame
// ends with one output transform that encodes for the display, and encoding here as well is the
// chapter's washed-out double-gamma picture.
#include "../../common/scene_uniforms.glsl"
#include "../../common/lighting.glsl"

// Material textures are sRGB textures, so sampling them returns linear values already.
layout(binding = kBaseColorTextureBinding) uniform sampler2D baseColorTexture;
layout(binding = kEmissiveTextureBinding) uniform sampler2D emissiveTexture;
// The largest value written (effects/scene/hdr_scene_pass.hpp: kSceneHdrMax).
layout(location = kHdrMaxLocation) uniform float hdrMax;

layout(location = 1) in vec2 texcoord;
layout(location = 2) in vec3 worldNormal;
layout(location = 0) out vec4 color;

void main() {
    vec3 albedo = baseColor * texture(baseColorTexture, texcoord).rgb;
    vec3 emitted = emissiveColor * texture(emissiveTexture, texcoord).rgb;
    vec3 linear = diffuseLighting(worldNormal, albedo) + emitted;
    // A half float is infinite above 65504, and one infinite or NaN texel spreads through every blur
    // after it: write a finite range, and 0 where something upstream produced NaN.
    linear = mix(clamp(linear, 0.0, hdrMax), vec3(0.0), isnan(linear));
    color = vec4(linear, 1.0);
}
