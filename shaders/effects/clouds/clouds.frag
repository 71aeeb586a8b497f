#version 450 core
// Ray-marched clouds (effects/clouds/cloud_pass.hpp; the Clouds chapter, its final algorithm in part 3).
// One full-screen pass drawn over the scene's colour with src-alpha blending: rgb is the cloud's
// colour, alpha how much of the scene behind it the cloud hides.
//
// Positions are kept relative to the camera: the ray is rotated from view space with the inverse
// view's rotation alone, and the camera's position is folded into the texture offsets on the CPU (in
// double), so a camera 10 km from the origin loses nothing to float cancellation.
#include "../../common/shadow_lookup.glsl"

#include "clouds_bindings.glsl"

layout(location = 1) in vec2 uv;
layout(location = 0) out vec4 color;

layout(binding = 0) uniform sampler2D density;     // sRGB8_ALPHA8: .r is sRGB-decoded, as in the chapter
layout(binding = 1) uniform sampler2D sceneDepth;  // plain sampler: the scene's depth buffer, [0, 1]

layout(location = kCloudsInverseProjectionLocation) uniform mat4 inverseProjection;
layout(location = kCloudsViewToWorldRotationLocation) uniform mat3 viewToWorldRotation;  // the inverse view matrix without its translation
layout(location = kCloudsCameraPositionLocation) uniform vec3 cameraPosition;       // world space
// Texture offsets, xy for layer 0 and zw for layer 1, with the camera's own position already added.
layout(location = kCloudsOffsetsLocation) uniform vec4 offsets;
layout(location = kCloudsRangeCountStepLocation) uniform vec4 rangeCountStep;  // bottom, top, samples, vertical step (cloud_march.hpp)
layout(location = kCloudsThresholdPairLocation) uniform vec2 thresholdPair;   // threshold, 1 / (1 - threshold) (0: no cloud)
layout(location = kCloudsColourLocation) uniform vec3 cloudColour;
layout(location = kCloudsScalesLocation) uniform vec2 scales;  // texture repeats per metre, layer 0 and layer 1
layout(location = kCloudsShadowOffsetLocation) uniform float shadowOffset;  // metres: one texel of the shadow map
layout(location = kCloudsFrameIndexLocation) uniform int frameIndex;      // moves the IGN and R2 patterns every frame
layout(location = kCloudsPlaneHeightLocation) uniform float planeHeight;   // stages 0 and 1
// The target's size: the pixel's position on the screen is gl_FragCoord / targetSize, exact at pixel
// centres, and it indexes the depth texture (the same size) directly.
layout(location = kCloudsTargetSizeLocation) uniform vec2 targetSize;
// Scene depth texels per pixel of this target: 1 at full resolution, 2 at half.
layout(location = kCloudsDepthStrideLocation) uniform int depthStride;

// What the whole draw shares is built into the program, one program per combination (#defines set by
// cloud_pass.cpp through effects/post/fullscreen_variants.hpp), not read from uniforms: llvmpipe runs
// both sides of a branch on a uniform, so every stage, feature and dither was paid for on every pixel.
//   CLOUD_STAGE        0: texture on the screen, 1: one plane, 2: march the slab
//   CLOUD_FEATURES     the feature bits below
//   CLOUD_DITHER       0 none, 1 Bayer 4x4, 2 IGN, 3 R2
//   CLOUD_PREMULTIPLY  1: write premultiplied colour (rgb x alpha) into a cloud layer of its own, for
//                      accumulation and upsampling; 0: straight alpha, blended over the scene directly
//                      (the chapter).
//   CLOUD_MIPMAPS      1: density lookups at the level of the pixel's footprint (a texture with mipmaps);
//                      0: level 0, the chapter's one-level texture, which shimmers far away.

// Feature bits (CloudFeature in cloud_pass.hpp).
const int kRejectBehind = 1;       // plane: no hit behind the eye (no mirrored layer)
const int kTwoScales = 2;          // the second layer at its own scale and offset
const int kDepthAware = 4;         // the scene's depth limits the ray
const int kEyeInside = 8;          // march from the eye when it is inside the slab, and stop at its faces
const int kShadows = 16;           // object shadows on the clouds
const int kThreshold = 32;         // coverage threshold
const int kHeightShaping = 64;     // thinner toward the top
const int kDistanceOcclusion = 128;  // compare distances along the ray, not heights
const int kBeerLambert = 256;      // opacity from the step's length: the same picture at any count

const float kDensityScale = 0.3;  // the chapter's most opacity one sample adds (per unit of density)
const float kShadowScale = 0.5;   // the chapter's strongest darkening
// Rays closer to horizontal than this (sine of about 5.7 degrees) take the step of this slope: the
// chapter's cap on the march length (10 x the slab's thickness).
const float kMinSlope = 0.1;
// A ray whose |v.y| is below this is parallel to the planes: no division by it.
const float kParallel = 1e-7;

bool has(int bit) { return (CLOUD_FEATURES & bit) != 0; }

// The width (m) one pixel covers on a horizontal layer at distance t along a ray whose vertical part is
// vy: the pixel's angle (from the inverse projection: tan(fovY / 2) over half the target's height) times
// t, stretched along the ray by 1 / |vy| (held at the march's slope cap).
float pixelFootprint(float t, float vy) {
    return t * 2.0 * inverseProjection[1][1] / targetSize.y / max(abs(vy), kMinSlope);
}

// The level whose texel is the footprint at `scale` repeats per metre (0 without mipmaps).
float densityLevel(float footprint, float scale) {
#if CLOUD_MIPMAPS
    return log2(max(footprint * abs(scale) * float(textureSize(density, 0).x), 1e-6));
#else
    return 0.0;
#endif
}

float sampleDensity(vec2 xz, float footprint) {
    // textureLod: the lookups sit in per-pixel control flow, where implicit derivatives are undefined, so
    // the level comes from the footprint computed here.
    float a = textureLod(density, xz * scales.x + offsets.xy, densityLevel(footprint, scales.x)).r;
    if (has(kTwoScales)) a += textureLod(density, xz * scales.y + offsets.zw, densityLevel(footprint, scales.y)).r;
    return a;
}

float bayer(ivec2 p) {
    const float m[16] = float[16](0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5);
    return m[(p.y & 3) * 4 + (p.x & 3)] / 16.0;
}

float ditherOffset() {
    vec2 p = floor(gl_FragCoord.xy);
    if (CLOUD_DITHER == 1) return bayer(ivec2(p));
    float shift = 5.588238 * float(frameIndex % 64);
    if (CLOUD_DITHER == 2) {
        // Interleaved gradient noise (Jimenez 2014), moved every frame.
        vec2 q = p + shift;
        return fract(52.9829189 * fract(0.06711056 * q.x + 0.00583715 * q.y));
    }
    if (CLOUD_DITHER == 3) {
        // Roberts' R2 sequence over the screen: low-discrepancy, its spectrum close to blue noise.
        return fract(0.5 + 0.7548776662 * p.x + 0.5698402910 * p.y + 0.618034 * float(frameIndex % 64));
    }
    return 0.0;
}

// The scene surface seen through this pixel, relative to the camera (or the far-plane point on sky
// pixels): the chapter's reconstruction, with the same inverse projection that drew the scene.
vec3 surfaceFromCamera(float depth01) {
    vec2 screen = gl_FragCoord.xy / targetSize;
    vec4 ndc = vec4(screen * 2.0 - 1.0, depth01 * 2.0 - 1.0, 1.0);
    vec4 h = inverseProjection * ndc;
    // The perspective divide done by hand; w is never 0 for a perspective inverse, but guard it.
    vec3 viewPos = h.xyz / (abs(h.w) > 1e-30 ? h.w : 1e-30);
    return viewToWorldRotation * viewPos;
}

void march();

void main() {
    march();
    if (CLOUD_PREMULTIPLY != 0) color.rgb *= color.a;
}

void march() {
    color = vec4(0.0);
    if (CLOUD_STAGE == 0) {
        // Step 1: the texture glued to the screen.
        color = vec4(cloudColour, textureLod(density, uv, 0.0).r);
        return;
    }
    ivec2 depthTexel = min(ivec2(gl_FragCoord.xy) * max(depthStride, 1), textureSize(sceneDepth, 0) - 1);
    float depth01 = has(kDepthAware) ? texelFetch(sceneDepth, depthTexel, 0).r : 1.0;
    bool sky = depth01 >= 1.0;
    vec3 w = surfaceFromCamera(depth01);  // W - camera
    float surfaceDistance = length(w);
    if (!(surfaceDistance > 0.0)) return;
    vec3 v = w / surfaceDistance;
    float camY = cameraPosition.y;
    float vy = abs(v.y) >= kParallel ? v.y : 0.0;  // below this, exactly parallel: no division at all

    if (CLOUD_STAGE == 1) {
        // Steps 2 to 4: one infinite plane. t = (planeY - camY) / v.y; a parallel ray never meets it.
        if (vy == 0.0) return;
        float t = (planeHeight - camY) / vy;
        if (has(kRejectBehind) && t < 0.0) return;  // behind the eye: without this, a mirrored layer
        // Depth: the hit must be in front of the surface; along a ray y is monotonic, so the chapter
        // compares heights (down: hit above the surface; up: hit below it).
        if (has(kDepthAware)) {  // on a sky pixel W is the far-plane point, as in the chapter
            float surfaceY = camY + w.y;
            bool inFront = vy < 0.0 ? planeHeight >= surfaceY : planeHeight <= surfaceY;
            if (!inFront) return;
        }
        vec3 hit = v * t;
        color = vec4(cloudColour, clamp(sampleDensity(hit.xz, pixelFootprint(t, vy)), 0.0, 1.0));
        return;
    }

    // Stage 2: march the slab between bottom and top.
    float bottom = rangeCountStep.x, top = rangeCountStep.y;
    int count = int(rangeCountStep.z);
    float stepY = rangeCountStep.w;
    float thickness = top - bottom;
    if (count <= 0 || !(thickness > 0.0) || !(stepY > 0.0)) return;

    float tmin, tmax;
    if (vy == 0.0) {
        // Parallel to the planes: inside the slab (faces included) the whole ray is in it, else none.
        if (camY < bottom || camY > top) return;
        tmin = 0.0;
        tmax = 3.0e38;
    } else {
        float t0 = (bottom - camY) / vy, t1 = (top - camY) / vy;
        tmin = min(t0, t1);
        tmax = max(t0, t1);
    }
    if (has(kEyeInside)) {
        tmin = max(tmin, 0.0);  // the chapter's fix: inside the slab, start at the eye
        if (tmin > tmax) return;
    } else if (tmin < 0.0) {
        return;  // §1.8: march only when the whole slab is ahead (the eye inside sees nothing)
    }
    // Occlusion by distance along the ray (beyond the chapter): the march stops at the surface.
    bool byDistance = has(kDistanceOcclusion) && has(kDepthAware);
    if (byDistance && !sky) {
        tmax = min(tmax, surfaceDistance);
        if (tmin > tmax) return;
    }
    float rangeMin = bottom, rangeMax = top;
    // The chapter's heights: on a sky pixel W is the far-plane point, so the far plane is the clouds'
    // draw distance (hard case 5); the distance test below leaves sky pixels unlimited instead.
    if (has(kDepthAware) && !byDistance) {
        float surfaceY = camY + w.y;
        rangeMin = max(surfaceY, bottom);
        rangeMax = min(surfaceY, top);
    }
    if (!has(kEyeInside)) {
        // Before the chapter's §2.1 the samples are tested against the object only, not the faces.
        rangeMin = has(kDepthAware) ? camY + w.y : -3.0e38;
        rangeMax = has(kDepthAware) ? camY + w.y : 3.0e38;
    }

    vec3 stepVec = v * (stepY / max(abs(vy), kMinSlope));
    float stepLength = length(stepVec);
    vec3 p = v * tmin + stepVec * ditherOffset();
    float dens = 0.0, shadow = 0.0;
    vec3 lit = vec3(0.0);
    // Beyond the chapter: opacity from the length of the step, Beer-Lambert. The extinction is chosen
    // so that a vertical ray through 1/8 of the slab gets the chapter's 0.3 x a (for small a).
    float sigmaPerDensity = kDensityScale * 8.0 / thickness;
    for (int i = 0; i < count; ++i) {
        float y = camY + p.y;
        float tHere = dot(p, v);
        bool inRange = vy < 0.0 ? y >= rangeMin : y <= rangeMax;
        if (has(kEyeInside)) inRange = inRange && y >= bottom - 1e-3 * thickness && y <= top + 1e-3 * thickness;
        if (byDistance) inRange = inRange && tHere <= tmax;
        if (inRange) {
            float a = sampleDensity(p.xz, pixelFootprint(tHere, vy));
            if (has(kHeightShaping)) a *= clamp((top - y) / thickness, 0.0, 1.0) * 0.5 + 0.5;
            if (has(kThreshold)) a = clamp(a - thresholdPair.x, 0.0, 1.0) * thresholdPair.y;
            float T = max(1.0 - dens, 0.0);
            float alpha = has(kBeerLambert) ? 1.0 - exp(-sigmaPerDensity * a * stepLength)
                                            : min(a * kDensityScale, 1.0);
            float s = 0.0;
            if (has(kShadows)) {
                // Pulled back toward the camera by one shadow texel: clouds have no normal to offset along.
                vec3 q = cameraPosition + p - v * shadowOffset;
                s = 1.0 - shadowVisibility(q, vec3(0.0));
            }
            if (has(kBeerLambert)) {
                // Shadow weighted by what the sample adds, so empty shadowed air darkens nothing.
                lit += T * alpha * (1.0 - kShadowScale * s) * cloudColour;
            } else {
                // The chapter: the shadow term is not weighted by the sample's density.
                shadow += s * T * kDensityScale;
            }
            dens += alpha * T;
        }
        p += stepVec;
        // Nothing more can change the result: the ray has left the slab or reached the surface (every
        // later sample fails the test), or the cloud is opaque (every later sample is weighted by T = 0).
        if (tHere > tmax + stepLength || dens >= 0.9999) break;
    }
    dens = clamp(dens, 0.0, 1.0);
    if (has(kBeerLambert)) {
        color = vec4(dens > 1e-6 ? lit / dens : cloudColour, dens);
    } else {
        shadow = min(shadow, 1.0) * kShadowScale;
        color = vec4(cloudColour * (1.0 - shadow), dens);
    }
}
