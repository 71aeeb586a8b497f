#version 450 core
// The off-screen particles (premultiplied, possibly at a half or quarter of the resolution) laid over
// the scene, upsampled by the bilinear filter; blended ONE, ONE_MINUS_SRC_ALPHA. Additive light sums
// without limit in the off-screen target; the clamp here keeps scene.color (16-bit floats, 65504 at
// most) finite: it gains at most hdrMax.
#include "common/scene_bindings.glsl"

layout(location = 1) in vec2 uv;
layout(binding = 0) uniform sampler2D particles;
layout(location = kHdrMaxLocation) uniform float hdrMax;
layout(location = 0) out vec4 outColor;

void main() {
    vec4 p = texture(particles, uv);
    outColor = vec4(clamp(p.rgb, vec3(0.0), vec3(hdrMax)), clamp(p.a, 0.0, 1.0));
}
