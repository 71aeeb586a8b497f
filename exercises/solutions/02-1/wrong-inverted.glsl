// Exercise 02-1, a typical wrong answer: the test turned round, so the holes cast and the bars do not.
bool castsShadow(vec4 baseColor, float alphaCutoff) {
    return baseColor.a < alphaCutoff;
}
