#version 450 core
// The chapter's first depth of field: 13 taps of its Poisson disk, scaled by (raw depth - 0.935) * 0.1
// in texture coordinates. Raw depth is not a distance, the scale is signed (it only mirrors the
// pattern) and isotropic in texture coordinates, so the blur is an ellipse in pixels.
#include "poisson.glsl"

#include "dof_bindings.glsl"

layout(binding = 0) uniform sampler2D scene;
layout(binding = 1) uniform sampler2D depth;
layout(location = kDofNaiveLocation) uniform vec2 naive;  // the depth that stays sharp (0.935), the scale (0.1)

layout(location = 1) in vec2 uv;
layout(location = 0) out vec4 color;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float scale = (texelFetch(depth, p, 0).r - naive.x) * naive.y;
    vec3 sum = texelFetch(scene, p, 0).rgb;
    for (int i = 0; i < 12; ++i) sum += texture(scene, uv + kPoisson[i] * scale).rgb;
    color = vec4(sum / 13.0, 1.0);
}
