#version 450 core
// The deferred lighting pass: one full-screen triangle reads the G-buffer under each pixel, rebuilds
// the surface's world position, and adds the light of the scene's sun (with its shadow), the ambient
// light and the point lights, all in linear HDR. LAYOUT as in gbuffer.frag. TILED: only the lights
// the culling pass listed for the pixel's tile (tiled_culling.comp), else every light.
#include "../../common/scene_uniforms.glsl"
#include "../../common/shadow_lookup.glsl"
#include "gbuffer_read.glsl"
#include "point_lights.glsl"

#include "deferred_bindings.glsl"

layout(location = kHdrMaxLocation) uniform float hdrMax;
layout(location = kSkyLocation) uniform vec3 sky;
// The whole scene moved this far from the origin (the shadow map was drawn where it is unmoved).
layout(location = kWorldOffsetLocation) uniform vec3 worldOffset;

#ifdef TILED
layout(std430, binding = kTileLightsBinding) readonly buffer TileLights {
    uint tileLights[];  // per tile: the count, then up to MAX_TILE_LIGHTS indices
};
layout(location = kTilesXLocation) uniform int tilesX;
#endif

layout(location = 0) out vec4 color;

const float kSpecular = 0.3;
const float kShininess = SHININESS;  // 40 in the lessons (DeferredLighting's constructor)

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 albedo = texelFetch(albedoTarget, p, 0);
    float depth = texelFetch(depthTarget, p, 0).r;
    if (albedo.a < 0.5 || depth >= 1.0) {
        color = vec4(sky, 1.0);  // no surface: the cleared normal and position mean nothing here
        return;
    }
    vec3 world = worldPositionAt(p, depth);
    vec3 n = normalAt(p);
    vec3 toEye = cameraPosition - world;
    float eyeDistance = length(toEye);
    vec3 v = eyeDistance > 1e-6 ? toEye / eyeDistance : n;

    float sun = max(dot(n, toLight), 0.0) * shadowVisibility(world - worldOffset, n);
    vec3 light = albedo.rgb * (ambientLight + lightColor * sun);
#ifdef TILED
    ivec2 tile = p / TILE_SIZE;
    uint base = uint(tile.y * tilesX + tile.x) * uint(MAX_TILE_LIGHTS + 1);
    int count = int(min(tileLights[base], uint(MAX_TILE_LIGHTS)));
    for (int k = 0; k < count; ++k)
        light += pointLightAt(int(tileLights[base + 1u + uint(k)]), world, n, v, albedo.rgb, kSpecular, kShininess);
#else
    for (int i = 0; i < pointLightCount; ++i)
        light += pointLightAt(i, world, n, v, albedo.rgb, kSpecular, kShininess);
#endif
    // A half float is infinite above 65504: write a finite range, and 0 for NaN (docs/numbers.md).
    color = vec4(mix(clamp(light, 0.0, hdrMax), vec3(0.0), isnan(light)), 1.0);
}
