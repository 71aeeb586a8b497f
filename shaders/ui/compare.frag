#version 450 core
// The compare view (ui/picture_view.cpp): the previous step's picture against this one, drawn into
// the picture's place in the window. mode 1: split, the previous step left of a white line and this
// step right of it; mode 2: the difference |this - previous| times `gain`, so a change of a few
// levels shows (a change of 1/255 becomes 8/255 at the default gain of 8).
layout(binding = 0) uniform sampler2D current;
layout(binding = 1) uniform sampler2D previous;
layout(location = 0) uniform int mode;
layout(location = 1) uniform vec4 place;  // x, y (bottom-left, window pixels), width, height
layout(location = 2) uniform float gain;
layout(location = 0) out vec4 colour;

// The texel of `picture` under the place's point `uv`: a picture may be smaller than its place (the
// frame budget's scale) or of another size than the other (the window was resized since): scaled to fit.
vec3 at(sampler2D picture, vec2 uv) {
    ivec2 size = textureSize(picture, 0);
    return texelFetch(picture, clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1), 0).rgb;
}

void main() {
    vec2 local = gl_FragCoord.xy - place.xy;
    vec2 uv = local / max(place.zw, vec2(1.0));
    vec3 now = at(current, uv);
    vec3 before = at(previous, uv);
    if (mode == 1) {
        float middle = floor(place.z * 0.5);
        if (abs(local.x - middle) < 1.0) {
            colour = vec4(1.0);
            return;
        }
        colour = vec4(local.x < middle ? before : now, 1.0);
    } else {
        colour = vec4(min(abs(now - before) * gain, vec3(1.0)), 1.0);
    }
}
