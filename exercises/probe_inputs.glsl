// The numbers the exercises' probes feed a student's code: fixed for a pixel, different from pixel to
// pixel (an integer hash, never fract(sin()), so every machine gets the same inputs).
uint probeHash(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

// A number in [0, 1) for a pixel and a channel (each channel its own stream).
float probeRandom(ivec2 pixel, uint channel) {
    uint h = probeHash(uint(pixel.x) * 73856093u ^ uint(pixel.y) * 19349663u ^ probeHash(channel + 1u));
    return float(h >> 8u) * (1.0 / 16777216.0);
}

// A unit vector for a pixel (channels base to base + 2).
vec3 probeDirection(ivec2 pixel, uint base) {
    vec3 v = vec3(probeRandom(pixel, base), probeRandom(pixel, base + 1u), probeRandom(pixel, base + 2u)) * 2.0 - 1.0;
    return length(v) > 1e-3 ? normalize(v) : vec3(0.0, 1.0, 0.0);
}
