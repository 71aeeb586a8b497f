// Exercise 10-1: the homework's planar reflection (lessons/10_deferred_shading/lesson.md, step 7).
// A mirror's plane is (n, d): the points p with dot(n, p) + d = 0, n a unit vector pointing out of the
// mirror's front. The reflection is drawn with the view V * R, where R reflects every point in the
// plane; while it is drawn, gl_ClipDistance[0] = dot(clip.xyz, p) + clip.w keeps what is in front of
// the mirror (>= 0) and drops what is behind it, with the plane raised kClipAbove metres so that the
// mirror itself stays out of its reflection.
const float kClipAbove = 0.001;

// R: the point p goes to its mirror image across the plane.
mat4 reflectionMatrix(vec4 plane) {
    // TODO
    return mat4(1.0);
}

// The clip plane that keeps what is kClipAbove or more in front of the mirror.
vec4 reflectionClipPlane(vec4 plane) {
    // TODO: as it stands, everything is kept.
    return vec4(0.0, 0.0, 0.0, 1.0);
}
