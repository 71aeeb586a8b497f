// Exercise 08-1, a typical wrong answer: the transmittance (what gets through) instead of the opacity.
float stepOpacity(float a, float sigmaPerDensity, float stepLength) {
    return exp(-sigmaPerDensity * a * stepLength);
}
