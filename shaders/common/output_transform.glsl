#include "srgb.glsl"

// Linear light to what the display expects (sRGB encoding), applied once, at the very end.
vec3 linearToSrgb(vec3 linear) {
    return srgbEncode(clamp(linear, 0.0, 1.0));
}

// Optional tone curves for HDR light, per channel, before linearToSrgb (which clips to [0, 1]):
// 0 none (the chapters: everything above 1 clips), 1 Reinhard x / (1 + x), 2 an ACES-style filmic
// curve (Narkowicz's fit of the ACES reference transform). Negative and NaN input give 0, and input
// is capped at a half float's 65504, so infinity gives white instead of Inf / Inf.
vec3 toneCurve(vec3 linear, int curve) {
    vec3 x = mix(clamp(linear, 0.0, 65504.0), vec3(0.0), isnan(linear));
    if (curve == 1) return x / (1.0 + x);
    if (curve == 2) return clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
    return linear;
}
