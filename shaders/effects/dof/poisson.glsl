// The chapter's 12-point Poisson disk in the unit disk (radii 0.51 to 0.99; its mean is (0.030,
// -0.105), so a strong blur drifts by about a tenth of its radius: hard case 11). With the centre
// tap, 13 taps.
const vec2 kPoisson[12] = vec2[12](vec2(-0.326, -0.406), vec2(-0.840, -0.074), vec2(-0.696, 0.457),
                                   vec2(-0.203, 0.621), vec2(0.962, -0.195), vec2(0.473, -0.480),
                                   vec2(0.519, 0.767), vec2(0.185, -0.893), vec2(0.507, 0.064),
                                   vec2(0.896, 0.412), vec2(-0.322, -0.933), vec2(-0.792, -0.598));
