// Exercise 08-1, a typical wrong answer: the first term of the exponential, which grows past 1 on long
// or dense steps.
float stepOpacity(float a, float sigmaPerDensity, float stepLength) {
    return sigmaPerDensity * a * stepLength;
}
