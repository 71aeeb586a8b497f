// Exercise 08-1, a solution: what is not transmitted over the step is its opacity.
float stepOpacity(float a, float sigmaPerDensity, float stepLength) {
    return 1.0 - exp(-sigmaPerDensity * a * stepLength);
}
