// Exercise 10-1, a solution. A point's signed distance to the plane is s = dot(n, p) + d; its image
// is p - 2 s n = (I - 2 n n^T) p - 2 d n: a 3x3 part and a translation in the fourth column.
const float kClipAbove = 0.001;

mat4 reflectionMatrix(vec4 plane) {
    vec3 n = plane.xyz;
    mat4 r = mat4(mat3(1.0) - 2.0 * outerProduct(n, n));
    r[3] = vec4(-2.0 * plane.w * n, 1.0);
    return r;
}

vec4 reflectionClipPlane(vec4 plane) {
    return vec4(plane.xyz, plane.w - kClipAbove);  // the plane moved kClipAbove along n
}
