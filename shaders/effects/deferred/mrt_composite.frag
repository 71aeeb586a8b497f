#version 450 core
// The lecture's "lighting" pass: one full-screen triangle that adds the three stored terms. All three
// targets were cleared to 0 (a glClear of the MRT framebuffer would put the sky colour in each and
// show the background three times as bright), so the sky is added once here, where no surface is.
//
// SHARPEN: the slides' edge-enhancement variant on the diffuse term, the 4-neighbour kernel
//    0 -1  0
//   -1  5 -1        D' = 5 c - (up + left + right + down) = c - Laplacian(c)
//    0 -1  0
// It sums to 1 (flat areas stay as they are); for inputs in [0, 1] its output lies in [-4, 5]. The
// sum goes to two targets: output 0 an RGBA8 target (clipped to [0, 1], as the slides' GL_RGBA is),
// output 1 a float one (kept). texelFetch at the pixel: the targets have the output's size.
#include "deferred_bindings.glsl"

layout(binding = 0) uniform sampler2D diffuseTerm;
layout(binding = 1) uniform sampler2D specularTerm;
layout(binding = 2) uniform sampler2D ambientTerm;
layout(location = kMrtSkyLocation) uniform vec3 sky;

layout(location = 0) out vec4 color;
#ifdef SHARPEN
layout(location = 1) out vec4 colorFloat;
#endif

vec3 diffuseAt(ivec2 p) {
    // Outside the image the edge texel repeats (clamp to edge): a flat border has no Laplacian.
    return texelFetch(diffuseTerm, clamp(p, ivec2(0), textureSize(diffuseTerm, 0) - 1), 0).rgb;
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 d = diffuseAt(p);
#ifdef SHARPEN
    d = 5.0 * d - diffuseAt(p + ivec2(0, 1)) - diffuseAt(p + ivec2(-1, 0)) - diffuseAt(p + ivec2(1, 0)) -
        diffuseAt(p + ivec2(0, -1));
#endif
    vec4 a = texelFetch(ambientTerm, p, 0);
    vec3 sum = d + texelFetch(specularTerm, p, 0).rgb + a.rgb + (1.0 - a.a) * sky;
    color = vec4(sum, 1.0);
#ifdef SHARPEN
    colorFloat = vec4(sum, 1.0);
#endif
}
