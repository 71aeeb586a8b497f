#version 450 core
// The gather's input at its resolution (half, or full when scale is 1): each texel averages its
// scale x scale block of the scene, and keeps the block's CoC of largest magnitude (the near one when
// a near and a far CoC tie), as a signed blur radius in the gather's own pixels. Blocks past the last
// full row or column (odd sizes) read the edge.
#include "coc.glsl"

#include "dof_bindings.glsl"

layout(binding = 0) uniform sampler2D scene;
layout(binding = 1) uniform sampler2D cocTexture;
layout(location = kDofPrefilterScaleLocation) uniform int scale;  // full-resolution pixels per gather pixel: 1 or 2

layout(location = 0) out vec4 color;

void main() {
    ivec2 last = textureSize(scene, 0) - 1;
    ivec2 base = ivec2(gl_FragCoord.xy) * scale;
    vec3 sum = vec3(0.0);
    float nearest = 0.0, farthest = 0.0;
    for (int y = 0; y < scale; ++y) {
        for (int x = 0; x < scale; ++x) {
            ivec2 q = min(base + ivec2(x, y), last);
            sum += texelFetch(scene, q, 0).rgb;
            float c = texelFetch(cocTexture, q, 0).r;
            nearest = min(nearest, c);
            farthest = max(farthest, c);
        }
    }
    float c = -nearest >= farthest ? nearest : farthest;
    color = vec4(sum / float(scale * scale), sign(c) * blurRadiusPixels(c) / float(scale));
}
