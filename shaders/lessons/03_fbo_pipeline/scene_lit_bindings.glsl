// Lesson 03's scene shader: the one uniform it adds to a shadowed scene shader's (scene_bindings.glsl),
// for the shader and lit_scene_pass.cpp alike.
const int kEncodeForDisplayLocation = 31;  // int: 1 ends with the display encoding
