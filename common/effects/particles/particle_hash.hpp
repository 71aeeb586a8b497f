#pragma once
// The particles' random numbers: an integer hash of (seed, spawn number, channel), never fract(sin()),
// so a run repeats byte for byte and the CPU and the GPU draw the same numbers. The GLSL twin is
// shaders/effects/particles/particle_common.glsl; tests compare the two.
#include <cstdint>

namespace fx {

// PCG's output permutation on one 32-bit word (Jarzynski and Olano, "Hash Functions for GPU
// Rendering", 2020): cheap, and every input bit reaches every output bit.
std::uint32_t pcgHash(std::uint32_t v);

// A number in [0, 1) for spawn `number` of the emitter seeded `seed`; `channel` picks one of several
// independent numbers for the same particle (0: angle, 1 and 2: sideways speed, 3: rise factor).
float particleRandom(std::uint32_t seed, std::uint32_t number, std::uint32_t channel);

}  // namespace fx
