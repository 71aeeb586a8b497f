#version 450 core
// The lecture's MRT fragment shader (Deferred rendering chapter, the three-target example): diffuse,
// specular and ambient light to outputs 0, 1 and 2, which go to the first, second and third entry of
// the framebuffer's draw-buffer list. Without THREE_TARGETS it writes their sum to one target:
// the render-to-texture step's forward picture.
#include "../../common/scene_uniforms.glsl"
#include "phong.glsl"

layout(binding = kBaseColorTextureBinding) uniform sampler2D baseColorTexture;
layout(binding = kEmissiveTextureBinding) uniform sampler2D emissiveTexture;

layout(location = 1) in vec2 texcoord;
layout(location = 2) in vec3 worldNormal;
layout(location = 3) in vec3 worldPosition;

#ifdef THREE_TARGETS
layout(location = 0) out vec4 diffuse;
layout(location = 1) out vec4 specular;
layout(location = 2) out vec4 ambient;
#else
layout(location = 0) out vec4 color;
#endif

void main() {
    vec3 albedo = baseColor * texture(baseColorTexture, texcoord).rgb;
    vec3 emitted = emissiveColor * texture(emissiveTexture, texcoord).rgb;
    PhongTerms t = phongTerms(worldNormal, worldPosition, albedo);
#ifdef THREE_TARGETS
    // Alpha: the lecture's choice (ambient 1, the others 0) makes the sum's alpha exactly 1, and the
    // ambient target's alpha says "a surface is here" to the composite (the background is added there).
    diffuse = vec4(t.diffuse, 0.0);
    specular = vec4(t.specular, 0.0);
    ambient = vec4(t.ambient + emitted, 1.0);
#else
    color = vec4(t.ambient + t.diffuse + t.specular + emitted, 1.0);
#endif
}
