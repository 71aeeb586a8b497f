// Exercise 08-1: the Beer-Lambert step (lessons/08_clouds/lesson.md, "Exercise 1").
// The chapter's march adds min(a * 0.3, 1) of opacity per sample whatever the step's length, so the
// picture changes with the sample count. Light through a medium of extinction sigma (per metre, per
// unit of density) keeps exp(-sigma * a * length) of itself over a step of that length.
// `./fxlab check 08 1` compares your opacity over many densities and step lengths.

// The opacity (0: clear, 1: opaque) one march step of `stepLength` metres through density `a` adds.
float stepOpacity(float a, float sigmaPerDensity, float stepLength) {
    // TODO: from the step's length, not the chapter's fixed 0.3.
    return min(a * 0.3, 1.0);
}
