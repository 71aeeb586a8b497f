#version 450 core
// The signed CoC of every pixel, from the scene's depth (dof.coc, R32F: read back by the tests).
#include "coc.glsl"

layout(binding = 0) uniform sampler2D depth;

layout(location = 0) out float coc;

void main() {
    coc = signedCocPixels(texelFetch(depth, ivec2(gl_FragCoord.xy), 0).r);
}
