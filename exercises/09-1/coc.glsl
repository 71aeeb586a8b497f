// Exercise 09-1: the thin-lens circle of confusion (lessons/09_depth_of_field/lesson.md, "Exercise 1").
// This file stands in for shaders/effects/dof/coc.glsl: the lesson's CoC heat map and its blurs, and
// `./fxlab check 09 1`, build from it. signedCocPixels is yours to write; the rest is given. The CoC
// is a diameter in pixels, negative in front of the focus plane (near field), positive behind it.
#include "effects/dof/dof_bindings.glsl"

layout(location = kDofDepthRangeLocation) uniform vec2 depthRange;  // the projection's near and far planes (m)
layout(location = kDofLensLocation) uniform vec4 lens;        // 1/P (1/m), K (px m), max |CoC| (px), radius per diameter

// View-space distance for a window-space depth of a standard projection (depth range 0..1). The
// chapter's ToRealZ without 2d - 1: n f / (f - d (f - n)) keeps its precision near d = 1 (the sky).
// Depths outside [0, 1] are clamped: beyond the far plane counts as the far plane.
float linearDepthM(float depth) {
    float d = clamp(depth, 0.0, 1.0);
    float n = depthRange.x, f = depthRange.y;
    return n * f / (f - d * (f - n));
}

// The signed CoC diameter in pixels of the point at window-space depth `depth`, from the thin lens
// (lens.x is 1/P, lens.y is the lens's scale K, lens.z the largest |CoC| in pixels).
float signedCocPixels(float depth) {
    // TODO: 0 on the focus plane, negative in front of it, positive behind it, never beyond lens.z.
    return 0.0;
}

// The blur's radius in pixels for a CoC diameter: half of it, or (the chapter) all of it.
float blurRadiusPixels(float cocDiameter) {
    return abs(cocDiameter) * lens.w;
}
