// Exercise 04-1: the sepia filter and the negative as 4x4 affine matrices
// (lessons/04_colour_matrix/lesson.md, "Exercise 1"). A colour goes through them as
//     rgb' = (M * vec4(rgb, 1.0)).rgb
// so the fourth column can hold what a 3x3 cannot: an added constant. `./fxlab check 04 1` puts
// known colours through both matrices and compares them with the lesson's transforms.
//
// Remember how GLSL fills a matrix from a list of numbers: column by column.

// The chapter's sepia (step 3): red' = 0.346 r + 0.678 g + 0.151 b, green' = 0.278 r + 0.546 g +
// 0.124 b, blue' = 0.196 r + 0.385 g + 0.089 b.
mat4 sepiaAffine() {
    // TODO
    return mat4(1.0);
}

// The negative: every channel c becomes 1 - c.
mat4 invertAffine() {
    // TODO
    return mat4(1.0);
}
