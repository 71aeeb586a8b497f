// The post passes' uniform locations (shaders/effects/post/), written once for the shaders and the
// C++ (effects/post/post_bindings.hpp). Each pass is its own program, so the numbers repeat across
// passes; within a program they do not (unit.bindings checks both).
// output_transform.frag
const int kOutputDividerLocation = 0;   // int: the first pixel column that shows the main input
const int kOutputExposureLocation = 2;  // float
// ui_badge.frag
const int kUiPanelLocation = 0;  // vec4: x, y, width, height in window pixels
// colour_matrix.frag (its hdrMax is scene_bindings.glsl's kHdrMaxLocation)
const int kColourMatrixLocation = 200;  // mat3, column-major
const int kColourOffsetLocation = 201;  // vec3
// radial_blur_offset.glsl (both radial blur programs) and radial_blur.frag
const int kBlurCentreLocation = 0;      // vec2, framebuffer pixels
const int kBlurLengthLocation = 1;      // float: the chapter's z
const int kBlurStartLocation = 2;       // float: the chapter's w
const int kBlurFormulaLocation = 3;     // int
const int kBlurSamplesLocation = 4;     // int: the blur only
const int kBlurTargetSizeLocation = 5;  // vec2
