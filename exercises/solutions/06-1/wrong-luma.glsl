// Exercise 06-1, a typical wrong answer: the luma decides instead of the brightest channel.
vec3 brightPass(vec3 colour, float threshold) {
    float b = dot(colour, vec3(0.2126, 0.7152, 0.0722));
    return colour * (max(b - threshold, 0.0) / max(b, 1e-5));
}
