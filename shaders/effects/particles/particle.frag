#version 450 core
// The particle's colour. Only the sprite's alpha shapes it (the chapter's black base colour plus
// emission). Two blends, built into the program (PARTICLE_PREMULTIPLIED):
//   0, straight alpha (steps 1 to 4): out = (emission, alpha), blended SRC_ALPHA, ONE_MINUS_SRC_ALPHA;
//   1, premultiplied (step 5): out = (emission * a, a * coverage), blended ONE, ONE_MINUS_SRC_ALPHA,
//   so fire (coverage 0: adds light) and smoke (coverage 1: covers) share one blend state and one draw.
// The emission is clamped to hdrMax (docs/numbers.md). With PARTICLE_SOFT 1 the particle fades out
// where it nears the scene's surface (depth read as a texture, linearised first); with 0 the program
// has no depth read at all. Both are #defines, not uniforms, because llvmpipe runs both sides of a
// branch on a uniform: the depth fetch and its arithmetic would cost every pixel with the fade off.
// Whether the emitter has a sprite stays a flat input: it differs between the emitters of one draw.
#ifndef PARTICLE_SOFT
#error "PARTICLE_SOFT and PARTICLE_PREMULTIPLIED are set by ParticleRenderer"
#endif

#include "common/scene_bindings.glsl"
#include "particles_bindings.glsl"

layout(location = 0) in vec2 corner;
layout(location = 1) in vec4 color;
layout(location = 2) flat in vec3 emitterFlags;  // coverage, textured, the chapter's unclamped alpha
layout(location = 3) in float viewDistance;

layout(binding = kParticleSpriteBinding) uniform sampler2D sprite;
layout(location = kHdrMaxLocation) uniform float hdrMax;
#if PARTICLE_SOFT
layout(binding = kParticleSceneDepthBinding) uniform sampler2D sceneDepth;
layout(location = kParticleSoftDistanceLocation) uniform float softDistance;  // > 0 (ParticleRenderer builds this only then)
layout(location = kParticleNearFarLocation) uniform vec2 nearFar;
layout(location = kParticleDepthTexelsPerPixelLocation) uniform vec2 depthTexelsPerPixel;

// Distance from the camera of a [0, 1] depth-buffer value under a perspective projection.
float linearDepth(float depth, float near, float far) {
    return near * far / max(far - depth * (far - near), 1e-6);
}
#endif

layout(location = 0) out vec4 outColor;

void main() {
    float shape;
    if (emitterFlags.y > 0.5) {
        shape = texture(sprite, corner * 0.5 + 0.5).a;
    } else {
        shape = 1.0 - smoothstep(0.2, 1.0, length(corner));  // a soft dot
    }
    vec3 emission = clamp(color.rgb, vec3(0.0), vec3(hdrMax));
    // The chapter passes alpha on unclamped (below 0 after a long frame: the blend subtracts).
    float alpha = emitterFlags.z > 0.5 ? color.a : clamp(color.a, 0.0, 1.0);
    alpha *= shape;

#if PARTICLE_SOFT
    ivec2 texel = ivec2(gl_FragCoord.xy * depthTexelsPerPixel);
    float scene = linearDepth(texelFetch(sceneDepth, texel, 0).r, nearFar.x, nearFar.y);
    // Behind the scene's surface: 0 (the depth test, done here); in front: a smooth ramp.
    float fade = smoothstep(0.0, 1.0, clamp((scene - viewDistance) / max(softDistance, 1e-4), 0.0, 1.0));
    alpha *= fade;
#endif

#if PARTICLE_PREMULTIPLIED
    outColor = vec4(emission * alpha, alpha * emitterFlags.x);
#else
    outColor = vec4(emission, alpha);
#endif
}
