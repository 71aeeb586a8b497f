// The bloom passes' uniform locations, written once for the shaders and the C++
// (effects/bloom/bloom_bindings.hpp). Which filter, the Karis average, the wide top level and the tone
// curve are not uniforms: each program is built with its own (BLOOM_FILTERS, BLOOM_KARIS, BLOOM_WIDE,
// TONE_CURVE; effects/post/fullscreen_variants.hpp says why).
const int kBloomThresholdLocation = 1;  // float: extract.frag
const int kBloomKneeLocation = 2;       // float: extract.frag
const int kBloomScaleLocation = 3;      // float: extract.frag
const int kBloomOffsetLocation = 4;     // float, texels: extract, downsample, upsample, composite_present
const int kBloomUpScaleLocation = 6;    // float: upsample.frag and composite_present.frag
const int kBloomExposureLocation = 9;   // float: composite_present.frag
// gaussian.frag (the reference)
const int kGaussianDirectionLocation = 0;  // ivec2: (1, 0) or (0, 1)
const int kGaussianSigmaLocation = 1;      // float, output pixels
const int kGaussianScaleLocation = 2;      // float
// flicker.frag
const int kFlickerHasPreviousLocation = 0;  // bool: false on the first frame
