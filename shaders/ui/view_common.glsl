// Shared by the inspector's shaders: view transforms, depth linearisation, the colours that mark
// values which are not numbers, and the checkerboard behind transparent or missing texels.

const int kDirect = 0;
const int kSrgb = 1;
const int kReinhard = 2;
const int kFalseColour = 3;

// The marks for special values (the legend in the overlay uses the same colours).
const vec3 kNanColour = vec3(1.0, 0.0, 1.0);          // magenta, as in the captures
const vec3 kInfColour = vec3(1.0, 0.78, 0.0);         // amber
const vec3 kNegativeColour = vec3(0.0, 0.67, 1.0);    // azure

// srgbEncode: the sRGB encoding of values in [0, 1], within 1/90 of an 8-bit step of
// image/view_transform.cpp's exact one (a fit: llvmpipe's pow() is slow).
#include "../common/srgb.glsl"

// A perceptual ramp from dark blue through green and yellow to dark red (a few control points of
// a turbo-like map, blended linearly): cold is low, hot is high.
vec3 falseColour(float x) {
    const vec3 stops[6] = vec3[6](vec3(0.19, 0.07, 0.23), vec3(0.16, 0.47, 0.93), vec3(0.10, 0.85, 0.62),
                                  vec3(0.73, 0.95, 0.22), vec3(0.98, 0.54, 0.13), vec3(0.48, 0.02, 0.01));
    float s = clamp(x, 0.0, 1.0) * 5.0;
    int i = min(int(floor(s)), 4);
    return mix(stops[i], stops[i + 1], s - float(i));
}

// The view transforms in two halves, so that zoomed-out views can average between them:
// mapTransform is what each texel needs alone (values already mapped to the range and exposed), and
// its result is still linear; encodeTransform makes that display-ready in [0, 1]. For one texel,
// encodeTransform(mapTransform(v)) is the whole transform, as image/view_transform.cpp applies it.
vec3 mapTransform(vec3 v, int transform) {
    if (transform == kReinhard) {
        vec3 c = max(v, vec3(0.0));
        return c / (1.0 + c);
    }
    if (transform == kFalseColour) return vec3(clamp(max(max(v.r, v.g), v.b), 0.0, 1.0));
    return clamp(v, 0.0, 1.0);
}
vec3 encodeTransform(vec3 mapped, int transform) {
    if (transform == kSrgb || transform == kReinhard) return srgbEncode(mapped);
    if (transform == kFalseColour) return falseColour(mapped.r);
    return mapped;
}

// A perspective depth-buffer value (0 near, 1 far, the default glDepthRange) back to the distance
// along the view axis. d = 1 gives far, d = 0 gives near.
float linearizeDepth(float d, float near, float far) {
    float z = d * 2.0 - 1.0;
    return 2.0 * near * far / max(far + near - z * (far - near), 1e-30);
}

vec3 checker(vec2 pixel) {
    ivec2 cell = ivec2(floor(pixel / 8.0));
    return ((cell.x + cell.y) & 1) == 0 ? vec3(0.16) : vec3(0.22);
}
