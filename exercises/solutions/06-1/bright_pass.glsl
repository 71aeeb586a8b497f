// Exercise 06-1, a solution: the brightest channel b decides; the colour is scaled by (b - t) / b, so
// the channels keep their ratios. The 1e-5 keeps black (b = 0) at 0 instead of 0 / 0.
vec3 brightPass(vec3 colour, float threshold) {
    float b = max(colour.r, max(colour.g, colour.b));
    return colour * (max(b - threshold, 0.0) / max(b, 1e-5));
}
