#version 450 core
// The reference glow (effects/bloom/bloom_reference.hpp): one direction of a separable Gaussian at full
// resolution, 32-bit float, every tap read exactly (texelFetch, clamped to the edge like the chain's
// sampler) and weighted exp(-i^2 / 2 sigma^2) out to 3 sigma, the weights normalised to sum to 1.
// Slow on purpose: it is the answer the chain's few bilinear taps approximate.
#include "bloom_bindings.glsl"

layout(binding = 0) uniform sampler2D source;
layout(location = kGaussianDirectionLocation) uniform ivec2 direction;  // (1, 0) or (0, 1)
layout(location = kGaussianSigmaLocation) uniform float sigma;      // output pixels
layout(location = kGaussianScaleLocation) uniform float scale;

layout(location = 0) out vec4 color;

const int kMaxRadius = 512;

void main() {
    ivec2 size = max(textureSize(source, 0), ivec2(1));
    ivec2 here = ivec2(gl_FragCoord.xy);
    int radius = min(int(ceil(3.0 * sigma)), kMaxRadius);
    float falloff = -0.5 / max(sigma * sigma, 1e-6);
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    for (int i = -radius; i <= radius; ++i) {
        float w = exp(float(i * i) * falloff);
        ivec2 at = clamp(here + direction * i, ivec2(0), size - 1);
        sum += w * texelFetch(source, at, 0).rgb;
        weights += w;
    }
    // Alpha 0: the vertical passes add onto one target, whose alpha the clear sets to 1.
    color = vec4(scale * sum / weights, 0.0);
}
