// Octahedral normal encoding (the compact G-buffer): a unit vector onto the octahedron |x|+|y|+|z| = 1,
// the lower half folded over the diagonals, so two numbers in [-1, 1] hold any direction. The fold is
// where z = 0: |x| + |y| = 1 there, and both halves give the same point, so a normal exactly on it
// comes back unchanged. A normal of zero length has no direction: it is stored as (2, 2), outside the
// square, and decodes to the zero vector (ambient light only), never to NaN.
// effects/deferred/gbuffer_layout.hpp has the same functions in C++ for the tests.
const vec2 kNoNormal = vec2(2.0);

vec2 signNotZero(vec2 v) {
    return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0);
}

vec2 octahedralEncode(vec3 n) {
    float l1 = abs(n.x) + abs(n.y) + abs(n.z);
    if (!(l1 > 1e-20)) return kNoNormal;  // also NaN
    vec3 o = n / l1;
    return o.z >= 0.0 ? o.xy : (1.0 - abs(o.yx)) * signNotZero(o.xy);
}

vec3 octahedralDecode(vec2 e) {
    if (abs(e.x) > 1.5) return vec3(0.0);
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    float t = max(-n.z, 0.0);
    n.xy -= t * signNotZero(n.xy);
    return normalize(n);  // length >= 1/sqrt(3): never zero
}
