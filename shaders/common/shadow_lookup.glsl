// Shadow-map lookup for lit shaders (effects/shadow/shadow_map.hpp sets these with ShadowMap::bindForLookup).
// Locations 40 to 43 and texture unit 4 are the shadow's own (scene_bindings.glsl).
//
//   float shadowVisibility(vec3 worldPosition, vec3 worldNormal)   1: lit, 0: in shadow
//
// The map is a plain depth texture (GL_DEPTH_COMPONENT32F) read with texelFetch and compared here,
// not a sampler2DShadow: no sampler object or compare mode has to be set on a texture the frame graph
// pools and the inspector shows, and the result does not depend on the texture's filter state.
//  - Normal offset: the point looked up moves along the surface normal by normalOffset texels of the
//    map (in metres), more where the surface turns away from the light, so a surface does not shadow
//    itself in stripes (shadow acne) without the large depth bias that detaches shadows from feet.
//  - Depth bias: a small constant on top, in depth-buffer units.
//  - PCF: `taps` depth comparisons on a Vogel disc (a golden-angle spiral) of `filterRadius` texels,
//    averaged: a soft edge whose smoothness grows with the tap count while its width stays put.
// Outside the map (or beyond its far plane) everything is lit: the fit covers the receivers, and a
// hard black border would be worse than a missing shadow at the edge.
#include "common/scene_bindings.glsl"

layout(location = kShadowMatrixLocation) uniform mat4 shadowLightViewProjection;
// x: normal offset (metres), y: depth bias, z: filter radius (texels), w: 1 = shadows on, 0 = off
layout(location = kShadowParamsLocation) uniform vec4 shadowParams;
layout(location = kShadowTapsLocation) uniform int shadowFilterTaps;
layout(location = kShadowToLightLocation) uniform vec3 shadowDirectionToLight;
layout(binding = kShadowMapBinding) uniform sampler2D shadowMap;

const int kShadowMaxTaps = 64;
const float kGoldenAngle = 2.39996323;

float shadowVisibility(vec3 worldPosition, vec3 worldNormal) {
    if (shadowParams.w < 0.5) return 1.0;
    float len = length(worldNormal);
    vec3 n = len > 1e-6 ? worldNormal / len : vec3(0.0);
    // Grazing surfaces need the most offset: scale by the sine of the angle to the light.
    float cosine = clamp(dot(n, shadowDirectionToLight), 0.0, 1.0);
    float slope = sqrt(max(1.0 - cosine * cosine, 0.0));
    vec3 p = worldPosition + n * shadowParams.x * (0.5 + slope);
    vec4 clip = shadowLightViewProjection * vec4(p, 1.0);
    // Orthographic: w is 1, but a broken matrix must not divide by zero.
    vec3 ndc = clip.xyz / (abs(clip.w) > 1e-12 ? clip.w : 1.0);
    vec3 coord = ndc * 0.5 + 0.5;
    if (any(lessThan(coord.xy, vec2(0.0))) || any(greaterThan(coord.xy, vec2(1.0))) || coord.z > 1.0 ||
        any(isnan(coord)))
        return 1.0;
    ivec2 size = textureSize(shadowMap, 0);
    vec2 texel = coord.xy * vec2(size);
    float reference = coord.z - shadowParams.y;
    int taps = clamp(shadowFilterTaps, 1, kShadowMaxTaps);
    float lit = 0.0;
    for (int i = 0; i < taps; ++i) {
        vec2 offset = vec2(0.0);
        if (taps > 1) {
            float r = shadowParams.z * sqrt((float(i) + 0.5) / float(taps));
            float a = float(i) * kGoldenAngle;
            offset = r * vec2(cos(a), sin(a));
        }
        ivec2 at = clamp(ivec2(floor(texel + offset)), ivec2(0), size - 1);
        lit += texelFetch(shadowMap, at, 0).r >= reference ? 1.0 : 0.0;
    }
    return lit / float(taps);
}
