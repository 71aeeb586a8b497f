// The point lights of the deferred passes, in a storage buffer (effects/deferred/point_light_buffer.hpp):
// world position and radius, linear colour times intensity. A light reaches exactly `radius` metres:
//   attenuation(d) = (1 - (d / r)^2)^2 for d < r, else 0
// which is 1 at the light and at most 1 anywhere, so a light inside a surface (d = 0) is as bright as
// the light itself and no more, a light of radius 0 adds nothing, and N lights on one pixel add at most
// N times the brightest; the tiles' culling tests the same sphere.
struct PointLight {
    vec4 positionRadius;
    vec4 color;  // rgb: colour x intensity
};

#include "deferred_bindings.glsl"

layout(std430, binding = kPointLightsBinding) readonly buffer PointLights {
    PointLight pointLights[];
};

layout(location = kPointLightCountLocation) uniform int pointLightCount;

float pointLightAttenuation(float distance, float radius) {
    if (!(radius > 0.0) || distance >= radius) return 0.0;
    float x = distance / radius;
    float w = 1.0 - x * x;
    return w * w;
}

// The highlight's falloff max(n.h, 0)^shininess. GLSL leaves pow(0, 0) undefined (it is
// exp2(0 x log2(0)) = exp2(0 x -inf): NaN on many GPUs), and n.h is 0 where the half vector is
// perpendicular to the normal or zero; an exponent of 0 (or below) is a flat highlight, 1 everywhere.
// A huge exponent underflows to 0 below n.h = 1, which is the limit, and stays 1 at n.h = 1.
float specularFalloff(float nh, float shininess) {
    return shininess > 0.0 ? pow(nh, shininess) : 1.0;
}

// Diffuse + specular light from light `i` at world point p with unit (or zero) normal n, viewed
// along v (unit, from the point to the eye).
vec3 pointLightAt(int i, vec3 p, vec3 n, vec3 v, vec3 albedo, float specular, float shininess) {
    PointLight light = pointLights[i];
    vec3 toLight = light.positionRadius.xyz - p;
    float d = length(toLight);
    float att = pointLightAttenuation(d, light.positionRadius.w);
    if (att <= 0.0) return vec3(0.0);
    // At the light itself there is no direction: light the point as if from straight above it.
    vec3 l = d > 1e-4 ? toLight / d : n;
    float lambert = max(dot(n, l), 0.0);
    if (lambert <= 0.0) return vec3(0.0);
    vec3 h = l + v;
    float hLength = length(h);
    float nh = hLength > 1e-6 ? max(dot(n, h / hLength), 0.0) : 0.0;
    return att * light.color.rgb * (albedo * lambert + specular * specularFalloff(nh, shininess));
}
