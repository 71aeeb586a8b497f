#version 450 core
// Two pictures in the picture's place (ui/picture_view.cpp): the compare view (the previous step's
// picture first, this step's second) and an exercise's views (the student's probe result, the
// reference's). mode 0: the first alone; mode 1: split, the first left of a white line and the second
// right of it; mode 2: the difference |second - first| times `gain`, so a change of a few levels shows
// (a change of 1/255 becomes 8/255 at the default gain of 8).
// Values show as v * display.x + display.y (a probe's numbers: pixels, metres), the difference as
// |second - first| * display.x * gain; NaN and Inf are magenta in every mode.
layout(binding = 0) uniform sampler2D first;
layout(binding = 1) uniform sampler2D second;
layout(location = 0) uniform int mode;
// Where the pictures go: x, y (bottom-left, window pixels), width, height. The draw covers the picture's
// whole place; around this rectangle it is ground.
layout(location = 1) uniform vec4 picture;
layout(location = 2) uniform float gain;
layout(location = 3) uniform vec2 display;  // scale, offset
layout(location = 4) uniform vec3 ground;
layout(location = 0) out vec4 colour;

const vec3 kNotFinite = vec3(1.0, 0.0, 1.0);

// By the bits: a compiler may assume no NaN exists and fold isnan away.
bool finite(vec3 v) {
    uvec3 exponent = floatBitsToUint(v) & 0x7f800000u;
    return all(notEqual(exponent, uvec3(0x7f800000u)));
}

// The texel of `image` under the picture's point `uv` (nearest): a picture may be smaller than its place
// (the frame budget's scale, a probe's few pixels) or of another size than the other (the window was
// resized since): scaled to fit.
vec3 at(sampler2D image, vec2 uv) {
    ivec2 size = textureSize(image, 0);
    return texelFetch(image, clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1), 0).rgb;
}

vec3 shown(vec3 v) {
    return finite(v) ? clamp(v * display.x + display.y, 0.0, 1.0) : kNotFinite;
}

void main() {
    vec2 local = gl_FragCoord.xy - picture.xy;
    if (any(lessThan(local, vec2(0.0))) || any(greaterThanEqual(local, picture.zw))) {
        colour = vec4(ground, 1.0);
        return;
    }
    vec2 uv = local / max(picture.zw, vec2(1.0));
    vec3 a = at(first, uv);
    if (mode == 0) {
        colour = vec4(shown(a), 1.0);
        return;
    }
    vec3 b = at(second, uv);
    if (mode == 1) {
        float middle = floor(picture.z * 0.5);
        if (abs(local.x - middle) < 1.0) {
            colour = vec4(1.0);
            return;
        }
        colour = vec4(shown(local.x < middle ? a : b), 1.0);
    } else if (!finite(a) || !finite(b)) {
        colour = vec4(kNotFinite, 1.0);
    } else {
        colour = vec4(min(abs(b - a) * display.x * gain, vec3(1.0)), 1.0);
    }
}
