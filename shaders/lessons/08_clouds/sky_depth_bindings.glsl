// Lesson 08's sky that writes depth (sky_depth.frag), for the shader and clouds_lesson.cpp alike.
const int kSkyDepthLocation = 0;  // float: the depth the sky writes, in [0, 1]
