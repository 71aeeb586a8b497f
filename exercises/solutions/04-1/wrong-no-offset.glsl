// Exercise 04-1, a typical wrong answer: the negative as a bare -I, which maps black to black (and
// every colour below zero); the sepia is right.
mat4 sepiaAffine() {
    return mat4(0.346, 0.278, 0.196, 0.0,
                0.678, 0.546, 0.385, 0.0,
                0.151, 0.124, 0.089, 0.0,
                0.0, 0.0, 0.0, 1.0);
}

mat4 invertAffine() {
    return mat4(-1.0, 0.0, 0.0, 0.0,
                0.0, -1.0, 0.0, 0.0,
                0.0, 0.0, -1.0, 0.0,
                0.0, 0.0, 0.0, 1.0);
}
