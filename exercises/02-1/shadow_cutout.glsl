// Exercise 02-1: the alpha cutout of the shadow pass (lessons/02_skinned_shadows/lesson.md, step 5).
// The lattice mannequin's texture has square holes of alpha 0 between opaque bars. The shadow pass
// writes depth only, so a hole reaches the ground only if the pass drops the fragment there. Return
// whether a fragment with this base colour writes its depth into the shadow map, for the program's
// cutoff (the lesson's shadow_depth.frag drops fragments whose alpha is below it).
bool castsShadow(vec4 baseColor, float alphaCutoff) {
    // TODO: as it stands, every fragment casts (the chapter's solid shadow).
    return true;
}
