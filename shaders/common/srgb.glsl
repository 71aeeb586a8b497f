// The sRGB encoding (IEC 61966-2-1) of linear light already clamped to [0, 1], for every shader that
// encodes: the output transform and the inspector's views.
//
// Above the linear toe the exact curve is 1.055 c^(1/2.4) - 0.055. A GPU evaluates pow() in a few
// cycles, but llvmpipe (this project's CI) builds it from a log2 and an exp2 polynomial per channel,
// which cost 0.5 full-screen copies in lesson 06's final pass (docs/bench.md). Three square roots
// (single instructions on the CPU's vector units too) give c^(1/2), c^(1/4) and c^(1/8), and a sum of
// those with c itself, weighted by a minimax fit over [0.0031308, 1], stays within 4.5e-5 of the
// exact curve: 1/90 of an 8-bit step, so fewer than 1 % of 8-bit values round to the neighbouring
// level (tests/gl/test_srgb_encoding.cpp checks the bound on the GPU). The result is capped at 1
// because the fit overshoots by 4e-5 there.
vec3 srgbEncode(vec3 c) {
    vec3 r2 = sqrt(c), r4 = sqrt(r2), r8 = sqrt(r4);
    vec3 curve = min(0.64236689 * r2 + 0.71210902 * r4 - 0.33686933 * r8 - 0.017563556 * c, vec3(1.0));
    return mix(12.92 * c, curve, step(vec3(0.0031308), c));
}
