// Exercise 07-1, a typical wrong answer: 120 used as radians a second (sin and cos take radians).
vec2 spunCorner(vec2 corner, float angleAtBirth, float ageSeconds) {
    float angle = angleAtBirth + 120.0 * ageSeconds;
    float c = cos(angle), s = sin(angle);
    return mat2(c, s, -s, c) * corner;
}
