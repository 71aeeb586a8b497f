// Exercise 06-1: the bright pass that keeps the hue (lessons/06_bloom/lesson.md, steps 3 and 4).
// The bloom starts from the part of the scene above the threshold. Subtracting the threshold from each
// channel on its own changes the colour: (2, 0.5, 0) would become (1, 0, 0), a green-free red. The
// Bloom chapter lets the brightest channel decide how much of the colour is kept, and scales all
// three channels by that one factor. Black must stay black (and finite).
vec3 brightPass(vec3 colour, float threshold) {
    // TODO
    return max(colour - threshold, 0.0);
}
