#version 450 core
// The inspector's view of one level of a texture, drawn into an 8-bit target the overlay shows.
// Zoomed in, every display pixel shows exactly one texel (no filtering), so single texels are
// squares and the probe's numbers belong to the square under the cursor. Zoomed out, a pixel
// averages up to 4x4 texels of its footprint, so fine detail does not alias into patterns that are
// not in the texture; a NaN anywhere in the footprint still paints the whole pixel.
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
layout(location = 8) uniform int transform;        // kDirect, kSrgb, kReinhard, kFalseColour
layout(location = 9) uniform int linearDepth;      // 1: the value is a depth buffer's, linearise it
layout(location = 10) uniform vec2 nearFar;
layout(location = 11) uniform int highlight;       // 1: grey picture with the special texels in colour
layout(location = 12) uniform int grid;            // 1: outline texels (when they are large)

out vec4 color;

const int kOrdinary = 0;
const int kNegative = 1;
const int kInfinite = 2;
const int kNan = 3;

// One texel as the view shows it; `kind` says whether it holds a special value (the worst one).
vec3 shadeTexel(ivec2 texel, vec2 pixel, out int kind) {
    vec4 raw = texelFetch(source, texel, level);
    if (channelCount < 4) raw.a = 1.0;
    if (channelCount < 3) raw.b = 0.0;
    if (channelCount < 2) raw.g = 0.0;

    // Classified on the stored values, before anything is mapped.
    kind = kOrdinary;
    for (int c = 0; c < channelCount; ++c) {
        if (isnan(raw[c])) kind = max(kind, kNan);
        else if (isinf(raw[c])) kind = max(kind, kInfinite);
        else if (raw[c] < 0.0) kind = max(kind, kNegative);
    }

    vec4 v = raw;
    if (linearDepth == 1) v.r = linearizeDepth(raw.r, nearFar.x, nearFar.y);
    float span = range.y - range.x;
    vec4 mapped = (v - range.x) / (abs(span) > 1e-30 ? span : 1e-30) * exposure;

    // One channel alone (or a one-channel format) is shown as grey.
    int count = channelCount < 2 ? 1 : int(shown.r + shown.g + (channelCount > 2 ? shown.b : 0.0) +
                                           (channelCount > 3 ? shown.a : 0.0));
    vec3 rgb;
    bool overChecker = false;
    if (channelCount == 1) {
        rgb = vec3(mapped.r * shown.r);
    } else if (count == 1) {
        float g = shown.r > 0.5 ? mapped.r : shown.g > 0.5 ? mapped.g : shown.b > 0.5 ? mapped.b : mapped.a;
        rgb = vec3(g);
    } else {
        rgb = mapped.rgb * shown.rgb;
        overChecker = channelCount == 4 && shown.a > 0.5;
    }
    vec3 display = applyTransform(rgb, transform);
    if (overChecker) display = mix(checker(pixel), display, clamp(raw.a, 0.0, 1.0));
    if (highlight == 1) display = vec3(0.12 + 0.5 * dot(display, vec3(0.2126, 0.7152, 0.0722)));
    return display;
}

void main() {
    int n = int(clamp(ceil(texelsPerPixel - 1e-3), 1.0, 4.0));  // samples per axis in this pixel
    vec3 sum = vec3(0.0);
    int worst = kOrdinary;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            vec2 t = origin + (gl_FragCoord.xy - 0.5 + (vec2(i, j) + 0.5) / float(n)) * texelsPerPixel;
            ivec2 texel = ivec2(floor(t));
            if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, levelSize))) {
                sum += checker(gl_FragCoord.xy);
                continue;
            }
            int kind;
            sum += shadeTexel(texel, gl_FragCoord.xy, kind);
            worst = max(worst, kind);
        }
    }
    vec3 display = sum / float(n * n);
    if (highlight == 1 && worst == kNegative) display = kNegativeColour;
    if (highlight == 1 && worst == kInfinite) display = kInfColour;
    if (worst == kNan) display = kNanColour;  // always: a NaN must never blend in (as in the captures)

    if (grid == 1) {
        vec2 inTexel = fract(origin + gl_FragCoord.xy * texelsPerPixel);
        if (inTexel.x < texelsPerPixel || inTexel.y < texelsPerPixel) display *= 0.72;
    }
    color = vec4(display, 1.0);
}
