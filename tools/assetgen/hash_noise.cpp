#include "hash_noise.hpp"

namespace fx::assetgen {
namespace {

// Eight gradient directions (axes and diagonals), picked by three hash bits.
constexpr float kDiagonal = 0.70710678f;
constexpr float kGradients[8][2] = {{1, 0},
                                    {-1, 0},
                                    {0, 1},
                                    {0, -1},
                                    {kDiagonal, kDiagonal},
                                    {-kDiagonal, kDiagonal},
                                    {kDiagonal, -kDiagonal},
                                    {-kDiagonal, -kDiagonal}};

// Quintic fade: zero first and second derivatives at 0 and 1, so octaves join without creases.
float fade(float t) {
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}
float lerp(float a, float b, float t) {
    return a + (b - a) * t;
}

int wrap(int i, int period) {
    int m = i % period;
    return m < 0 ? m + period : m;
}

int floorToInt(float v) {
    int i = static_cast<int>(v);
    return (static_cast<float>(i) > v) ? i - 1 : i;
}

float cornerDot(int ix, int iy, float dx, float dy, int period, std::uint32_t seed) {
    std::uint32_t h = hash2(wrap(ix, period), wrap(iy, period), seed);
    const float* g = kGradients[h & 7u];
    return g[0] * dx + g[1] * dy;
}

}  // namespace

std::uint32_t hash32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x21f0aaadu;
    x ^= x >> 15;
    x *= 0xd35a2d97u;
    x ^= x >> 15;
    return x;
}

std::uint32_t hash2(std::int32_t x, std::int32_t y, std::uint32_t seed) {
    std::uint32_t h = hash32(static_cast<std::uint32_t>(x) * 0x9e3779b9u + seed);
    return hash32(h ^ (static_cast<std::uint32_t>(y) * 0x85ebca6bu + 0x27d4eb2fu));
}

float unitFloat(std::uint32_t h) {
    return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

float tileableGradientNoise(float x, float y, int period, std::uint32_t seed) {
    if (period < 1) period = 1;
    int ix = floorToInt(x), iy = floorToInt(y);
    float fx = x - static_cast<float>(ix), fy = y - static_cast<float>(iy);
    float n00 = cornerDot(ix, iy, fx, fy, period, seed);
    float n10 = cornerDot(ix + 1, iy, fx - 1.0f, fy, period, seed);
    float n01 = cornerDot(ix, iy + 1, fx, fy - 1.0f, period, seed);
    float n11 = cornerDot(ix + 1, iy + 1, fx - 1.0f, fy - 1.0f, period, seed);
    float u = fade(fx), v = fade(fy);
    // Scaled so the extremes of 2D gradient noise (about +-0.7) reach about +-1.
    return 1.41421356f * lerp(lerp(n00, n10, u), lerp(n01, n11, u), v);
}

float valueNoise1D(float x, std::uint32_t seed) {
    int i = floorToInt(x);
    float f = x - static_cast<float>(i);
    float a = unitFloat(hash2(i, 0, seed)), b = unitFloat(hash2(i + 1, 0, seed));
    return lerp(a, b, fade(f));
}

float tileableFbm(float x, float y, int basePeriod, int octaves, float gain, std::uint32_t seed) {
    float sum = 0.0f, amplitude = 1.0f, frequency = 1.0f;
    int period = basePeriod;
    for (int k = 0; k < octaves; ++k) {
        sum += amplitude * tileableGradientNoise(x * frequency, y * frequency, period,
                                                 seed + 0x632be5abu * static_cast<std::uint32_t>(k + 1));
        amplitude *= gain;
        frequency *= 2.0f;
        period *= 2;
    }
    return sum;
}

}  // namespace fx::assetgen
