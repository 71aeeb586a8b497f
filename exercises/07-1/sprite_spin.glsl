// Exercise 07-1: the chapter's Exercise 06, a fire sprite that turns at 120 degrees a second
// (lessons/07_fire_emitter/lesson.md, step 1). The billboard's corner (x and y in -1 to 1, along the
// view's own axes) is turned about the view axis after the billboard is built, so it always faces the
// camera. A particle is born at angle `angleAtBirth` (radians) and is `ageSeconds` old. Positive
// angles turn the view's x axis toward its y axis (counter-clockwise on the screen).
vec2 spunCorner(vec2 corner, float angleAtBirth, float ageSeconds) {
    // TODO
    return corner;
}
