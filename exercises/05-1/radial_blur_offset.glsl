// Exercise 05-1: the guarded start distance (lessons/05_radial_blur/lesson.md, "Exercise 1").
// This file stands in for shaders/effects/post/radial_blur_offset.glsl: the lesson's blur and
// `./fxlab check 05 1` both build from it. Only the guarded branch at the end is yours to write.
const int kFirstVersion = 0;  // v = d * length
const int kChapter = 1;       // v = d * (max(|d| - start, 0) / |d|) * length: 0/0 at the centre pixel
const int kGuarded = 2;       // the same, defined at the centre pixel
const float kCentreEpsilon = 1e-6;

#include "effects/post/post_bindings.glsl"

layout(location = kBlurCentreLocation) uniform vec2 centrePixels;
layout(location = kBlurLengthLocation) uniform float blurLength;     // the chapter's z
layout(location = kBlurStartLocation) uniform float startDistance;   // the chapter's w
layout(location = kBlurFormulaLocation) uniform int formula;
layout(location = kBlurTargetSizeLocation) uniform vec2 targetSize;  // at least 1x1

vec2 tapOffset(vec2 pixel) {
    vec2 d = (centrePixels - pixel) / targetSize;  // toward the centre, in texture coordinates
    if (formula == kFirstVersion) return d * blurLength;
    float lenA = length(d);
    float lenB = max(lenA - startDistance, 0.0);
    if (formula == kChapter) return d * (lenB / lenA) * blurLength;
    // TODO (kGuarded): the chapter's offset everywhere except at the centre pixel, where |d| is 0 and
    // lenB / lenA is 0 / 0. What should a pixel with no direction toward the centre do?
    return d * (lenB / lenA) * blurLength;
}
