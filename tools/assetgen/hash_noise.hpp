#pragma once
// Integer hashing and tileable noise for the generated textures. Everything is integer arithmetic or
// plain float +, -, * (no sin, no library calls), so every run on every machine gives the same values:
// the committed files are compared byte for byte with a fresh run.
#include <cstdint>

namespace fx::assetgen {

// A 32-bit avalanche hash: every input bit flips about half of the output bits.
std::uint32_t hash32(std::uint32_t x);
// Hash of a lattice point and a seed.
std::uint32_t hash2(std::int32_t x, std::int32_t y, std::uint32_t seed);
// The hash as a float in [0, 1).
float unitFloat(std::uint32_t h);

// Gradient noise on a lattice that repeats every `period` cells in x and y, so a texture that spans
// whole periods tiles without a seam. Roughly in [-1, 1], 0 at lattice points.
float tileableGradientNoise(float x, float y, int period, std::uint32_t seed);

// Value noise in one dimension (smooth, in [0, 1]), for gentle wobble along a line.
float valueNoise1D(float x, std::uint32_t seed);

// Fractal sum of gradient noise: octave k has period basePeriod * 2^k cells and amplitude gain^k.
// (x, y) are in units of the base period's cells; the result tiles over basePeriod cells.
float tileableFbm(float x, float y, int basePeriod, int octaves, float gain, std::uint32_t seed);

}  // namespace fx::assetgen
