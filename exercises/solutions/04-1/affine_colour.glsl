// Exercise 04-1, a solution. mat4(...) takes its numbers column by column, so each group of four
// below is one input channel's weights in the three outputs (and w); the last column is the offset.
mat4 sepiaAffine() {
    return mat4(0.346, 0.278, 0.196, 0.0,   // how much r adds to r', g', b'
                0.678, 0.546, 0.385, 0.0,   // g
                0.151, 0.124, 0.089, 0.0,   // b
                0.0, 0.0, 0.0, 1.0);        // no offset
}

// 1 - c: minus the identity, plus 1 in the offset column.
mat4 invertAffine() {
    return mat4(-1.0, 0.0, 0.0, 0.0,
                0.0, -1.0, 0.0, 0.0,
                0.0, 0.0, -1.0, 0.0,
                1.0, 1.0, 1.0, 1.0);
}
