#version 450 core
// A picture for the inspector's tests and documentation: HDR sky with a sun far above 1, coloured
// rings and fine stripes whose mip levels visibly average out. mode 1 presents a texture instead
// (Reinhard, then sRGB) so the picture behind the overlay is the one in the inspector.
#include "view_common.glsl"

layout(binding = 0) uniform sampler2D presented;
layout(location = 0) uniform int mode;
layout(location = 1) uniform vec2 size;
layout(location = 1) in vec2 uv;
out vec4 color;

vec3 hue(float h) {
    return clamp(abs(mod(h * 6.0 + vec3(0.0, 4.0, 2.0), 6.0) - 3.0) - 1.0, 0.0, 1.0);
}

void main() {
    if (mode == 1) {
        vec3 c = max(texture(presented, uv).rgb, vec3(0.0));
        color = vec4(srgbEncode(c / (1.0 + c)), 1.0);
        return;
    }
    vec2 p = uv * vec2(size.x / size.y, 1.0);
    // Sky: deep blue above, warm at the horizon (linear light).
    vec3 c = mix(vec3(0.9, 0.45, 0.2), vec3(0.05, 0.12, 0.45), smoothstep(0.25, 0.95, uv.y));
    // Ground with fine stripes: one texel wide at level 0, grey a few levels down.
    if (uv.y < 0.3) {
        float stripe = float((int(gl_FragCoord.x) + int(gl_FragCoord.y)) % 2);
        c = mix(vec3(0.05, 0.08, 0.04), vec3(0.35, 0.5, 0.2), stripe);
    }
    // Coloured rings.
    vec2 ringCentre = vec2(0.45, 0.42) * vec2(size.x / size.y, 1.0);
    float r = length(p - ringCentre);
    if (r < 0.3) c = mix(c, hue(r * 5.0) * 1.5, 0.85 * smoothstep(0.3, 0.27, r));
    // The sun: 30 times brighter than white, with a glow.
    vec2 sunCentre = vec2(0.78, 0.72) * vec2(size.x / size.y, 1.0);
    float d = length(p - sunCentre);
    c += vec3(1.0, 0.85, 0.6) * (d < 0.06 ? 30.0 : 0.003 / max(d * d, 1e-4));
    color = vec4(c, 1.0);
}
