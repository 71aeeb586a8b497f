// The offset between neighbouring taps of the radial blur (Shader effects chapter §3.6), shared by the blur
// and by the pass that writes the offsets for the inspector. Distances are in texture coordinates of
// the screen, as in the chapter; the centre comes in pixels so that the pixel sitting on it gets
// d = 0 exactly. effects/post/radial_blur.cpp holds the same maths on the CPU.
const int kFirstVersion = 0;  // v = d * length
const int kChapter = 1;       // v = d * (max(|d| - start, 0) / |d|) * length: 0/0 at the centre pixel
const int kGuarded = 2;       // the same, with v = 0 where |d| <= kCentreEpsilon
const float kCentreEpsilon = 1e-6;

#include "effects/post/post_bindings.glsl"

layout(location = kBlurCentreLocation) uniform vec2 centrePixels;
layout(location = kBlurLengthLocation) uniform float blurLength;     // the chapter's z
layout(location = kBlurStartLocation) uniform float startDistance;   // the chapter's w
layout(location = kBlurFormulaLocation) uniform int formula;
layout(location = kBlurTargetSizeLocation) uniform vec2 targetSize;  // at least 1x1

vec2 tapOffset(vec2 pixel) {
    vec2 d = (pixel - centrePixels) / targetSize;  // away from the centre (the sign error)
    if (formula == kFirstVersion) return d * blurLength;
    float lenA = length(d);
    float lenB = max(lenA - startDistance, 0.0);
    if (formula == kChapter) return d * (lenB / lenA) * blurLength;
    // The centre pixel has no direction toward the centre; its limit is "no blur".
    return lenA > kCentreEpsilon ? d * (lenB / lenA) * blurLength : vec2(0.0);
}
