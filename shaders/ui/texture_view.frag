#version 450 core
// The inspector's view of one level of a texture, drawn into an 8-bit target the overlay shows.
// Zoomed in, every display pixel shows exactly one texel (no filtering), so single texels are
// squares and the probe's numbers belong to the square under the cursor. Zoomed out, a pixel
// averages up to 4x4 texels of its footprint as light, so fine detail does not alias into patterns
// that are not in the texture; a NaN anywhere in the footprint still paints the whole pixel.
// Per texel, in order: depth linearised with the camera's planes -> value range mapped to [0, 1] ->
// exposure -> channel selection -> view transform -> NaN / Inf / negative marks; then the texel grid.
// The view transforms match image/view_transform.cpp (the captures) for Direct and sRGB.
#include "view_common.glsl"

layout(binding = 0) uniform sampler2D source;
layout(location = 0) uniform int level;
layout(location = 1) uniform ivec2 levelSize;
layout(location = 2) uniform vec2 origin;          // texel coordinate at the target's lower-left corner
layout(location = 3) uniform float texelsPerPixel;  // > 0
layout(location = 4) uniform int channelCount;     // what the format stores: 1 to 4
layout(location = 5) uniform vec4 shown;           // 1 for each channel toggled on
layout(location = 6) uniform vec2 range;           // the values shown as black and as white
layout(location = 7) uniform float exposure;       // a multiplier, 2^stops
// kDirect, kSrgb, kReinhard, kFalseColour: built into the program (ui/texture_display.hpp says why).
const int transform = VIEW_TRANSFORM;
layout(location = 9) uniform int linearDepth;      // 1: the value is a depth buffer's, linearise it
layout(location = 10) uniform vec2 nearFar;
layout(location = 11) uniform int highlight;       // 1: grey picture with the special texels in colour
layout(location = 12) uniform int grid;            // 1: outline texels (when they are large)

out vec4 color;

const int kOrdinary = 0;
const int kNegative = 1;
const int kInfinite = 2;
const int kNan = 3;

// One texel mapped for the view, still linear: depth linearised, range and exposure applied, the
// channels picked, and the part of the view transform that must see each texel alone (the clamp, the
// Reinhard curve, the largest channel for the false colour). `kind` says whether the texel holds a
// special value (the worst one); `alpha` is its coverage when the alpha channel is shown over the
// checkerboard, else 1.
vec3 mapTexel(ivec2 texel, out int kind, out float alpha) {
    vec4 raw = texelFetch(source, texel, level);
    if (channelCount < 4) raw.a = 1.0;
    if (channelCount < 3) raw.b = 0.0;
    if (channelCount < 2) raw.g = 0.0;

    // Classified on the stored values, before anything is mapped, on the channels the format has.
    bvec4 stored = lessThan(ivec4(0, 1, 2, 3), ivec4(channelCount));
    bvec4 nan = bvec4(uvec4(isnan(raw)) & uvec4(stored));
    bvec4 inf = bvec4(uvec4(isinf(raw)) & uvec4(stored));
    bvec4 negative = bvec4(uvec4(lessThan(raw, vec4(0.0))) & uvec4(stored));
    kind = any(nan) ? kNan : any(inf) ? kInfinite : any(negative) ? kNegative : kOrdinary;

    vec4 v = raw;
    if (linearDepth == 1) v.r = linearizeDepth(raw.r, nearFar.x, nearFar.y);
    float span = range.y - range.x;
    vec4 mapped = (v - range.x) / (abs(span) > 1e-30 ? span : 1e-30) * exposure;

    // One channel alone (or a one-channel format) is shown as grey.
    int count = channelCount < 2 ? 1 : int(shown.r + shown.g + (channelCount > 2 ? shown.b : 0.0) +
                                           (channelCount > 3 ? shown.a : 0.0));
    vec3 rgb;
    alpha = 1.0;
    if (channelCount == 1) {
        rgb = vec3(mapped.r * shown.r);
    } else if (count == 1) {
        float g = shown.r > 0.5 ? mapped.r : shown.g > 0.5 ? mapped.g : shown.b > 0.5 ? mapped.b : mapped.a;
        rgb = vec3(g);
    } else {
        rgb = mapped.rgb * shown.rgb;
        if (channelCount == 4 && shown.a > 0.5) alpha = clamp(raw.a, 0.0, 1.0);
    }
    return mapTransform(rgb, transform);
}

void main() {
    int n = int(clamp(ceil(texelsPerPixel - 1e-3), 1.0, 4.0));  // samples per axis in this pixel
    // Zoomed out, the texels of a pixel are averaged as light (before the display encoding, as a mip
    // level of an sRGB texture is), and encoded once per pixel: the encoding's pow() is the costly part.
    vec3 light = vec3(0.0);
    float coverage = 0.0;
    int inside = 0;
    int worst = kOrdinary;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            vec2 t = origin + (gl_FragCoord.xy - 0.5 + (vec2(i, j) + 0.5) / float(n)) * texelsPerPixel;
            ivec2 texel = ivec2(floor(t));
            if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, levelSize))) continue;
            int kind;
            float alpha;
            light += mapTexel(texel, kind, alpha);
            coverage += alpha;
            worst = max(worst, kind);
            ++inside;
        }
    }
    vec3 board = checker(gl_FragCoord.xy);
    vec3 display = board;  // outside the level: the checkerboard
    if (inside > 0) {
        display = encodeTransform(light / float(inside), transform);
        display = mix(board, display, coverage / float(inside));
        if (highlight == 1) display = vec3(0.12 + 0.5 * dot(display, vec3(0.2126, 0.7152, 0.0722)));
        // Samples that fell outside the level show the checkerboard in their share of the pixel.
        display = mix(board, display, float(inside) / float(n * n));
    }
    if (highlight == 1 && worst == kNegative) display = kNegativeColour;
    if (highlight == 1 && worst == kInfinite) display = kInfColour;
    if (worst == kNan) display = kNanColour;  // always: a NaN must never blend in (as in the captures)

    if (grid == 1) {
        vec2 inTexel = fract(origin + gl_FragCoord.xy * texelsPerPixel);
        if (inTexel.x < texelsPerPixel || inTexel.y < texelsPerPixel) display *= 0.72;
    }
    color = vec4(display, 1.0);
}
