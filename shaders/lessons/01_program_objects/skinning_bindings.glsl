// Lesson 01's skinning program: the two uniforms it adds to the scene's (scene_bindings.glsl), for the
// shader and program_objects_lesson.cpp alike.
const int kJointsLocation = 20;         // mat4[4]: locations 20 to 23
const int kSpheresPerRowLocation = 24;  // int
