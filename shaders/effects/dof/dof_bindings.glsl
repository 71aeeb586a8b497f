// The depth-of-field passes' uniform locations, written once for the shaders and the C++
// (effects/dof/dof_bindings.hpp).
// coc.glsl: in the programs that include it and use it (setting a location a program lacks is a GL
// error, so the C++ sets only what each pass's program has).
const int kDofDepthRangeLocation = 10;  // vec2: near and far, metres
const int kDofLensLocation = 11;        // vec4: 1/focus, pixels per metre, max CoC, radius per diameter
// naive.frag
const int kDofNaiveLocation = 0;  // vec2: sharp depth, scale
// prefilter.frag and gather.frag
const int kDofPrefilterScaleLocation = 0;  // int
// tile_max.frag
const int kDofTilePixelsLocation = 0;  // int
// gather.frag
const int kDofRingsLocation = 0;          // int
const int kDofTapsPerRingLocation = 1;    // int
const int kDofGatherTilePixelsLocation = 3;  // int
const int kDofMaxRadiusLocation = 4;      // float
const int kDofHighlightLocation = 5;      // float
const int kDofGatherScaleLocation = 6;    // int
// accumulate.frag (the reference)
const int kDofAccumulateWeightLocation = 0;  // float
