#version 450 core
// The cloud layer averaged over frames (effects/clouds/cloud_temporal.hpp): this frame's march mixed
// with last frame's result, reprojected and clamped to this frame's neighbourhood. Premultiplied RGBA.
#include "clouds_bindings.glsl"

layout(location = 0) out vec4 color;         // clouds.result, for the composite (and the bench)
layout(location = 1) out vec4 historyOut;    // the same, kept for next frame

layout(binding = 0) uniform sampler2D current;  // clouds.layer
layout(binding = 1) uniform sampler2D history;  // last frame's result, the same size
layout(binding = 2) uniform sampler2D sceneDepth;

layout(location = kAccumulateInverseProjectionLocation) uniform mat4 inverseProjection;
layout(location = kAccumulateViewToWorldRotationLocation) uniform mat3 viewToWorldRotation;
// Last frame's view-projection applied to positions relative to this frame's camera.
layout(location = kAccumulatePreviousFromCameraLocation) uniform mat4 previousFromCamera;
layout(location = kAccumulateSlabMiddleAndEyeYLocation) uniform vec2 slabMiddleAndEyeY;
layout(location = kAccumulateCurrentWeightLocation) uniform float currentWeight;  // 1: no history (the first frame of an average)
layout(location = kAccumulateTargetSizeLocation) uniform vec2 targetSize;
layout(location = kAccumulateDepthStrideLocation) uniform int depthStride;

void accumulate();

void main() {
    accumulate();
    historyOut = color;
}

void accumulate() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 last = textureSize(current, 0) - 1;
    vec4 now = texelFetch(current, p, 0);
    if (currentWeight >= 1.0) {
        color = now;
        return;
    }
    vec4 lo = now, hi = now;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            vec4 n = texelFetch(current, clamp(p + ivec2(dx, dy), ivec2(0), last), 0);
            lo = min(lo, n);
            hi = max(hi, n);
        }
    }
    // Where this pixel's cloud is taken to be: its ray at the slab's middle, or the surface if nearer.
    float d = texelFetch(sceneDepth, min(p * max(depthStride, 1), textureSize(sceneDepth, 0) - 1), 0).r;
    vec4 h = inverseProjection * vec4(gl_FragCoord.xy / targetSize * 2.0 - 1.0, d * 2.0 - 1.0, 1.0);
    vec3 w = viewToWorldRotation * (h.xyz / (abs(h.w) > 1e-30 ? h.w : 1e-30));
    float distance = length(w);
    vec3 v = distance > 0.0 ? w / distance : vec3(0.0, 0.0, -1.0);
    float t = abs(v.y) > 1e-4 ? (slabMiddleAndEyeY.x - slabMiddleAndEyeY.y) / v.y : -1.0;
    if (!(t > 0.0)) t = 1.0e4;  // level or away from the middle: a far point, the direction alone
    if (d < 1.0) t = min(t, distance);
    vec4 clip = previousFromCamera * vec4(v * t, 1.0);
    color = now;
    if (clip.w > 1e-6) {
        vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
        if (all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)))) {
            vec4 before = clamp(texture(history, uv), lo, hi);
            color = mix(before, now, currentWeight);
        }
    }
}
