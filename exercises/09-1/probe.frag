#version 450 core
// The check of exercise 09-1: the signed CoC (R) and the blur radius it gives (G) of window-space
// depths from the near plane (left) to the sky (right), each row spread differently. The check sets
// the lens of coc.glsl from exercise.json: the chapter's focus distances.
#include "effects/dof/coc.glsl"

layout(location = 20) uniform vec2 probeSize;

layout(location = 0) out vec4 result;

void main() {
    vec2 cell = floor(gl_FragCoord.xy);
    float across = (cell.x + 0.5) / probeSize.x;
    // Row 0 is linear in depth (mostly near); higher rows push the samples toward the sky.
    float depth = pow(across, 1.0 / (1.0 + cell.y));
    float coc = signedCocPixels(depth);
    result = vec4(coc, blurRadiusPixels(coc), 0.0, 1.0);
}
