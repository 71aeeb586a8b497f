#include "effects/particles/particle_hash.hpp"

namespace fx {

std::uint32_t pcgHash(std::uint32_t v) {
    std::uint32_t state = v * 747796405u + 2891336453u;
    std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

float particleRandom(std::uint32_t seed, std::uint32_t number, std::uint32_t channel) {
    std::uint32_t h = pcgHash(seed ^ pcgHash(number ^ pcgHash(channel)));
    // The top 24 bits: exactly representable in a float, so the result is below 1.
    return float(h >> 8u) * (1.0f / 16777216.0f);
}

}  // namespace fx
