#version 450 core
// The G-buffer pass: geometry only, no light. What goes to which target depends on the layout
// (effects/deferred/gbuffer_layout.hpp; LAYOUT is one of its numbers):
//   output 0  albedo (RGBA8): base colour, alpha 1 = a surface is here
//   output 1  normal: octahedral in RG16F (compact), xyz in RGBA16F / RGBA32F (fat), or raw xyz in
//             RGBA8 without the n*0.5+0.5 remap (the classic bug: every negative component becomes 0)
//   output 2  world position (fat layouts only; the compact one rebuilds it from depth)
//   output 2 or 3 (REFERENCE_POSITION, the next free one) the world position in RGBA32F, to measure the others against
// Emission is not part of this lesson's G-buffer: the lighting pass adds no emissive term.
#include "../../common/scene_uniforms.glsl"
#include "octahedral.glsl"

layout(binding = kBaseColorTextureBinding) uniform sampler2D baseColorTexture;

layout(location = 1) in vec2 texcoord;
layout(location = 2) in vec3 worldNormal;
layout(location = 3) in vec3 worldPosition;

layout(location = 0) out vec4 albedo;
layout(location = 1) out vec4 normal;
#if LAYOUT != 0
layout(location = 2) out vec4 position;
#endif
#ifdef REFERENCE_POSITION
layout(location = REFERENCE_LOCATION) out vec4 referencePosition;
#endif

void main() {
    albedo = vec4(baseColor * texture(baseColorTexture, texcoord).rgb, 1.0);
    float len = length(worldNormal);
    vec3 n = len > 1e-6 ? worldNormal / len : vec3(0.0);
#if LAYOUT == 0
    normal = vec4(octahedralEncode(n), 0.0, 0.0);
#else
    normal = vec4(n, 1.0);
    // A half float is infinite beyond 65504 m (docs/numbers.md): a far-away scene clamps, stays finite.
    position = vec4(clamp(worldPosition, -65504.0, 65504.0), 1.0);
#endif
#ifdef REFERENCE_POSITION
    referencePosition = vec4(worldPosition, 1.0);
#endif
}
