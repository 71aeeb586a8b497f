// Exercise 02-1, a typical wrong answer: the first channel (red) tested instead of the alpha.
bool castsShadow(vec4 baseColor, float alphaCutoff) {
    return baseColor.r >= alphaCutoff;
}
