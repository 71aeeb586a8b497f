#version 450 core
// The largest blur radius in each tile of the gather's texels: r = the largest near-field radius, g =
// the largest of either field. The gather reads the tiles around a pixel to bound how far it looks.
// The last tile in a row or column also covers the texels left over when the size is not a multiple.
#include "dof_bindings.glsl"

layout(binding = 0) uniform sampler2D prefiltered;  // a = signed radius in gather pixels
layout(location = kDofTilePixelsLocation) uniform int tilePixels;

layout(location = 0) out vec2 tileMax;

void main() {
    ivec2 size = textureSize(prefiltered, 0);
    ivec2 tiles = max(size / tilePixels, ivec2(1));
    ivec2 t = ivec2(gl_FragCoord.xy);
    ivec2 begin = t * tilePixels;
    ivec2 end = min(mix(begin + tilePixels, size, equal(t, tiles - 1)), size);
    float nearMax = 0.0, anyMax = 0.0;
    for (int y = begin.y; y < end.y; ++y) {
        for (int x = begin.x; x < end.x; ++x) {
            float r = texelFetch(prefiltered, ivec2(x, y), 0).a;
            nearMax = max(nearMax, -r);
            anyMax = max(anyMax, abs(r));
        }
    }
    tileMax = vec2(nearMax, anyMax);
}
