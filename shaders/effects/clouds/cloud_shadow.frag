#version 450 core
// Cloud shadows on the ground (effects/clouds/cloud_shadow_pass.hpp; beyond the Clouds chapter): for
// each pixel, the scene surface rebuilt from the depth buffer with the matrices that drew it, then the
// same density the clouds are marched through, marched from that surface toward the sun between the
// slab's faces. The output is the transmittance, exp(-optical depth): exactly 1 where no cloud is in
// the way (sky pixels, surfaces above the slab, a sun at or below the horizon), below 1 under cloud.
//
// As in clouds.frag, positions stay relative to the camera and the camera's position is folded into
// the texture offsets on the CPU (in double).

#include "clouds_bindings.glsl"

layout(location = 1) in vec2 uv;
layout(location = 0) out vec4 transmittance;

layout(binding = 0) uniform sampler2D density;     // sRGB8_ALPHA8: .r is sRGB-decoded, as in the chapter
layout(binding = 1) uniform sampler2D sceneDepth;  // the scene's depth buffer, [0, 1]

layout(location = kCloudsInverseProjectionLocation) uniform mat4 inverseProjection;
layout(location = kCloudsViewToWorldRotationLocation) uniform mat3 viewToWorldRotation;
layout(location = kCloudsCameraPositionLocation) uniform vec3 cameraPosition;
layout(location = kCloudsOffsetsLocation) uniform vec4 offsets;        // layer 0 in xy, layer 1 in zw (cloudShaderOffsets)
layout(location = kCloudsRangeCountStepLocation) uniform vec4 rangeCountStep;  // bottom, top (the samples are this pass's own)
layout(location = kCloudsThresholdPairLocation) uniform vec2 thresholdPair;   // threshold, 1 / (1 - threshold) (0: no cloud)
layout(location = kCloudsScalesLocation) uniform vec2 scales;
layout(location = kCloudShadowToLightLocation) uniform vec3 toLight;     // unit vector toward the sun
layout(location = kCloudShadowSamplesLocation) uniform int samples;      // along each shadow ray
layout(location = kCloudShadowSigmaPerDensityLocation) uniform float sigmaPerDensity;  // extinction per metre per unit of density
layout(location = kCloudsTargetSizeLocation) uniform vec2 targetSize;

// A sun lower than this (sine of about 5.7 degrees) is treated as this high: the path through the slab
// is 1 / toLight.y times its thickness, and the guard keeps it (and the shadow's reach) finite.
const float kMinSunSlope = 0.1;

float sampleDensity(vec2 xz) {
    float a = textureLod(density, xz * scales.x + offsets.xy, 0.0).r;
    a += textureLod(density, xz * scales.y + offsets.zw, 0.0).r;
    return a;
}

void main() {
    transmittance = vec4(1.0);
    ivec2 texel = min(ivec2(gl_FragCoord.xy), textureSize(sceneDepth, 0) - 1);
    float depth01 = texelFetch(sceneDepth, texel, 0).r;
    float bottom = rangeCountStep.x, top = rangeCountStep.y;
    float thickness = top - bottom;
    // Sky, no slab, no samples, no cloud at this threshold, or no sun above the horizon: no shadow.
    if (depth01 >= 1.0 || !(thickness > 0.0) || samples <= 0 || thresholdPair.y <= 0.0 || !(toLight.y > 0.0))
        return;

    // The surface relative to the camera: the same reconstruction as clouds.frag.
    vec4 ndc = vec4(gl_FragCoord.xy / targetSize * 2.0 - 1.0, depth01 * 2.0 - 1.0, 1.0);
    vec4 h = inverseProjection * ndc;
    vec3 surface = viewToWorldRotation * (h.xyz / (abs(h.w) > 1e-30 ? h.w : 1e-30));
    float surfaceY = cameraPosition.y + surface.y;
    if (surfaceY >= top) return;  // above the layer: nothing between it and the sun

    // The part of the sun ray inside the slab: from max(surface, bottom) up to the top face.
    float slope = max(toLight.y, kMinSunSlope);
    float startY = max(surfaceY, bottom);
    float lengthPerMetreUp = 1.0 / slope;
    vec2 drift = toLight.xz / slope;  // horizontal metres per metre up
    float stepUp = (top - startY) / float(samples);
    float ds = stepUp * lengthPerMetreUp;  // path length of one sample
    float opticalDepth = 0.0;
    for (int i = 0; i < samples; ++i) {
        float y = startY + (float(i) + 0.5) * stepUp;  // midpoints: no dither, a fixed map
        vec2 xz = surface.xz + drift * (y - surfaceY);
        float a = sampleDensity(xz);
        a *= clamp((top - y) / thickness, 0.0, 1.0) * 0.5 + 0.5;  // the height shaping of step 8
        a = clamp(a - thresholdPair.x, 0.0, 1.0) * thresholdPair.y;
        opticalDepth += sigmaPerDensity * a * ds;
    }
    transmittance = vec4(vec3(clamp(exp(-opticalDepth), 0.0, 1.0)), 1.0);
}
