// Exercise 10-1, a typical wrong answer: the clip plane turned round, so it keeps what is behind the mirror.
const float kClipAbove = 0.001;

mat4 reflectionMatrix(vec4 plane) {
    vec3 n = plane.xyz;
    mat4 r = mat4(mat3(1.0) - 2.0 * outerProduct(n, n));
    r[3] = vec4(-2.0 * plane.w * n, 1.0);
    return r;
}

vec4 reflectionClipPlane(vec4 plane) {
    return -vec4(plane.xyz, plane.w - kClipAbove);
}
