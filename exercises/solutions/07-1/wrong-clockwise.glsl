// Exercise 07-1, a typical wrong answer: the rotation matrix transposed, so the sprite turns clockwise.
vec2 spunCorner(vec2 corner, float angleAtBirth, float ageSeconds) {
    float angle = angleAtBirth + radians(120.0) * ageSeconds;
    float c = cos(angle), s = sin(angle);
    return mat2(c, -s, s, c) * corner;
}
