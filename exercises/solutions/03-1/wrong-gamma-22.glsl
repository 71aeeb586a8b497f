// Exercise 03-1, a typical wrong answer: a plain power 1/2.2 instead of the sRGB curve.
vec3 windowValue(vec3 linearLight, bool framebufferEncodes) {
    vec3 c = clamp(linearLight, 0.0, 1.0);
    return framebufferEncodes ? c : pow(c, vec3(1.0 / 2.2));
}
