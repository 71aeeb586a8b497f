// Exercise 03-1: one output transform (lessons/03_fbo_pipeline/lesson.md, step 5). The frame is
// linear light in a float target; the last pass writes it to the window. Whether GL encodes what the
// shader writes depends on the window's framebuffer: with GL_FRAMEBUFFER_SRGB on an sRGB buffer, GL
// applies the sRGB curve itself; otherwise the shader must. Return what the last pass writes so that
// the screen shows sRGB exactly once, light above 1 clipped to white.
//
// The sRGB curve (IEC 61966-2-1): 12.92 c for c <= 0.0031308, else 1.055 c^(1/2.4) - 0.055.
vec3 windowValue(vec3 linearLight, bool framebufferEncodes) {
    // TODO
    return linearLight;
}
