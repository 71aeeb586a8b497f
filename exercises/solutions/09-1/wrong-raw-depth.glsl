// The signed circle of confusion of a thin lens (scene/thin_lens.hpp holds the same maths on the CPU,
// and the tests compare the two): a diameter in pixels, negative in front of the focus plane (near
// field), positive behind it (far field), clamped to +-maxCoc.
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

// K (1/P - 1/D): A I |1/D - 1/P| in pixels with the sign of the field. 0 exactly at D = P (the
// chapter's A F (P - D) / (D (P - F)) would be 0 * infinity there when P = F).
float signedCocPixels(float depth) {
    float c = lens.y * (lens.x - 1.0 / depth);  // the window-space depth, not metres
    return clamp(c, -lens.z, lens.z);
}

// The blur's radius in pixels for a CoC diameter: half of it, or (the chapter) all of it.
float blurRadiusPixels(float cocDiameter) {
    return abs(cocDiameter) * lens.w;
}
