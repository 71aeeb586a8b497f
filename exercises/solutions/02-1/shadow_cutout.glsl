// Exercise 02-1, a solution: the texture's alpha against the cutoff; a fragment exactly at the cutoff
// is kept, as shadow_depth.frag keeps it (it discards below).
bool castsShadow(vec4 baseColor, float alphaCutoff) {
    return baseColor.a >= alphaCutoff;
}
