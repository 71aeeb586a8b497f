// Exercise 04-1, a typical wrong answer: the sepia written row by row into mat4(...), which reads
// columns, so the matrix is transposed (and the offset row lands in w).
mat4 sepiaAffine() {
    return mat4(0.346, 0.678, 0.151, 0.0,
                0.278, 0.546, 0.124, 0.0,
                0.196, 0.385, 0.089, 0.0,
                0.0, 0.0, 0.0, 1.0);
}

mat4 invertAffine() {
    return mat4(-1.0, 0.0, 0.0, 1.0,
                0.0, -1.0, 0.0, 1.0,
                0.0, 0.0, -1.0, 1.0,
                0.0, 0.0, 0.0, 1.0);
}
