// Shared by the bloom passes (effects/bloom/bloom_chain.hpp). BLOOM_MAX_VALUE and BLOOM_MAX_BRIGHT come
// from the C++ side (effects/bloom/bloom_settings.hpp) as defines, so the limits live in one place.

// A colour made safe to filter and to store: NaN becomes 0 (GLSL leaves clamp(NaN) undefined, so it
// is picked out first), and the rest is clamped to [lo, hi], which also turns +-Inf into a limit.
// One bad texel then stays one bad texel instead of spreading through every level (Bloom chapter,
// hard cases 1 and 3).
vec3 finiteClamp(vec3 c, float lo, float hi) {
    return mix(clamp(c, lo, hi), vec3(0.0), isnan(c));
}

// The chapters' hue-preserving bright pass: the brightest channel b decides, and the colour is scaled
// by (b - threshold) / b, so (2, 0.5, 0) keeps its green: (1, 0.25, 0) (Bloom chapter, §1.5).
// knee > 0 rounds the corner at the threshold into a parabola (the quadratic soft knee), so a surface
// that creeps over the threshold fades in instead of switching on; knee 0 is the chapters' hard cut.
// The input must be >= 0: a negative channel would be scaled too and make a dark halo.
// A threshold below 0 counts as 0 here, in the effect and not only in a lesson's slider (Shader effects,
// hard case 9): unclamped, (b - threshold) / b exceeds 1 and grows without bound as b falls, so every
// pixel blooms and near-black ones most. Written as a comparison so a NaN threshold is 0 as well.
vec3 brightPart(vec3 c, float threshold, float knee) {
    threshold = threshold > 0.0 ? threshold : 0.0;
    float b = max(c.r, max(c.g, c.b));
    float hard = max(b - threshold, 0.0);
    float k = max(knee * threshold, 0.0);
    float s = clamp(b - threshold + k, 0.0, 2.0 * k);
    float soft = s * s / max(4.0 * k, 1e-5);
    float amount = k > 0.0 ? max(hard, soft) : hard;
    return c * (amount / max(b, 1e-5));  // 1e-5: black has b = 0 (the Bloom chapter's guard)
}

float luma(vec3 c) {
    return dot(c, vec3(0.2126, 0.7152, 0.0722));
}

// One source texel in texture coordinates; a zero-sized texture counts as one texel, so nothing
// divides by zero (the chain never makes one, but a shader must not trust that).
vec2 texelSize(sampler2D s) {
    return 1.0 / vec2(max(textureSize(s, 0), ivec2(1)));
}

// The four bilinear taps at (+-o.x, +-o.y) from uv, summed: the diagonals every bloom filter has.
vec3 diagonalSum(sampler2D source, vec2 uv, vec2 o) {
    return texture(source, uv + vec2(-o.x, o.y)).rgb + texture(source, uv + vec2(o.x, o.y)).rgb +
           texture(source, uv + vec2(-o.x, -o.y)).rgb + texture(source, uv + vec2(o.x, -o.y)).rgb;
}

// The upsample filters (effects/bloom/bloom_settings.hpp), `offset` in texels of `source`:
//   filters 0 (Shader effects): centre x3, 4 diagonals at +-offset x2, 4 axial at 2 offset x1, / 15;
//   filters 1 (Bloom chapter): 4 axial taps at 2 offset x1, 4 diagonal at offset x2, / 12;
//   filters 2: one bilinear tap.
// `source` must be sampled with GL_LINEAR (the chain's sampler): each tap then averages four texels.
vec3 upsampleFilter(sampler2D source, vec2 uv, int filters, float offset) {
    if (filters == 2) return texture(source, uv).rgb;
    vec2 o = offset * texelSize(source);
    vec3 diagonals = diagonalSum(source, uv, o);
    vec3 axial = texture(source, uv + vec2(-2.0 * o.x, 0.0)).rgb + texture(source, uv + vec2(2.0 * o.x, 0.0)).rgb +
                 texture(source, uv + vec2(0.0, -2.0 * o.y)).rgb + texture(source, uv + vec2(0.0, 2.0 * o.y)).rgb;
    return filters == 0 ? (3.0 * texture(source, uv).rgb + 2.0 * diagonals + axial) / 15.0
                        : (2.0 * diagonals + axial) / 12.0;
}

// The widening of the upsample for the top level when it also does the composite's blur (`wide` in
// upsample.frag): the composite's filter at this level's texels convolved with the upsample of the level
// below, whose texels are twice as large. Variances add: s^2 (here) + (2 s)^2 (below, in these texels) =
// 5 s^2, which is the same filter at sqrt(5) / 2 = 1.118 times its offset in the lower level's texels.
const float kWideUpsampleScale = 1.118034;

// The top level's blur of its own texels when it does the composite's work (`wide`): as wide as
// upsampleFilter with the same offset, in four bilinear taps instead of eight. Per axis, the Bloom
// chapter's filter has a variance of 16/12 offset^2 and the Shader effects one 16/15 offset^2 (the
// bilinear spread of each tap aside); four equal diagonal taps at +-d have d^2, so d is the square
// root of that. Half the taps, and against the direct Gaussians the error did not grow (docs/bench.md).
vec3 ownBlur(sampler2D level, vec2 uv, int filters, float offset) {
    float d = offset * (filters == 0 ? 1.032796 : 1.154701);
    return 0.25 * diagonalSum(level, uv, d * texelSize(level));
}
