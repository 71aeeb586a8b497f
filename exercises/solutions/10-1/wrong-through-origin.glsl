// Exercise 10-1, a typical wrong answer: the plane's offset d forgotten, so R reflects in a parallel
// plane through the origin.
const float kClipAbove = 0.001;

mat4 reflectionMatrix(vec4 plane) {
    return mat4(mat3(1.0) - 2.0 * outerProduct(plane.xyz, plane.xyz));
}

vec4 reflectionClipPlane(vec4 plane) {
    return vec4(plane.xyz, plane.w - kClipAbove);
}
