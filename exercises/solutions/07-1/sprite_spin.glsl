// Exercise 07-1, a solution: 120 degrees a second in radians, added to the angle at birth; the corner
// turned counter-clockwise by it (mat2 takes columns: the first is where x goes).
vec2 spunCorner(vec2 corner, float angleAtBirth, float ageSeconds) {
    float angle = angleAtBirth + radians(120.0) * ageSeconds;
    float c = cos(angle), s = sin(angle);
    return mat2(c, s, -s, c) * corner;
}
