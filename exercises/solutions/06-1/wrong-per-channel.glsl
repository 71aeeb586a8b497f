// Exercise 06-1, a typical wrong answer: the threshold subtracted from each channel (the hue shifts).
vec3 brightPass(vec3 colour, float threshold) {
    return max(colour - threshold, 0.0);
}
