#version 450 core
// One step down the chain (effects/bloom/bloom_chain.hpp): the next level at half the size, lightly blurred.
//   filters 0 (Shader effects): centre x4 plus 4 diagonal taps at +-offset (1) texels, / 8;
//   filters 1 (Bloom chapter): 4 diagonal taps at +-offset (0.75) texels, / 4: the [1 3 3 1]/8 binomial.
// Taps need GL_LINEAR and CLAMP_TO_EDGE (the chain binds its own sampler): each tap then averages four
// texels, and light from one edge does not wrap round to the other.
#include "bloom_common.glsl"

#include "bloom_bindings.glsl"

layout(binding = 0) uniform sampler2D source;
// Chosen when the program is built (effects/post/fullscreen_variants.hpp): a uniform here would make
// llvmpipe run every filter's taps for every pixel.
const int filters = BLOOM_FILTERS;
layout(location = kBloomOffsetLocation) uniform float offset;

layout(location = 1) in vec2 uv;
layout(location = 0) out vec4 color;

void main() {
    vec2 o = offset * texelSize(source);
    vec3 diagonals = diagonalSum(source, uv, o);
    vec3 c = filters == 0 ? (4.0 * texture(source, uv).rgb + diagonals) / 8.0 : diagonals / 4.0;
    color = vec4(finiteClamp(c, 0.0, BLOOM_MAX_VALUE), 1.0);
}
