// Exercise 03-1, a solution: clip first (the curve is defined on [0, 1]), then encode unless GL will.
vec3 encodeSrgbExactly(vec3 c) {
    vec3 curve = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
    return mix(12.92 * c, curve, step(vec3(0.0031308), c));
}

vec3 windowValue(vec3 linearLight, bool framebufferEncodes) {
    vec3 c = clamp(linearLight, 0.0, 1.0);
    return framebufferEncodes ? c : encodeSrgbExactly(c);
}
