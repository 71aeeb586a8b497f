#pragma once
// What one particle and one emitter look like in memory, on the CPU and in the GPU's buffers alike
// (std430: vec4s only, so the C++ and GLSL layouts match without padding rules). The GLSL twin is
// shaders/effects/particles/particle_common.glsl.
//
// A particle stores where and when it was born, not where it is: its position is origin + velocity *
// age, and its size, colour and angle follow from age / lifetime. So the per-frame simulation is one
// addition and one comparison per particle, and the CPU and GPU paths compute the same numbers.
#include <cstdint>

#include <glm/vec4.hpp>

namespace fx {

struct GpuParticle {
    glm::vec4 originAge{0.0f};     // xyz: where it was born (m); w: age (s)
    glm::vec4 velocityLife{0.0f};  // xyz: m/s; w: lifetime (s)
    glm::vec4 extra{0.0f};         // x: angle at birth (rad); y: emitter index; z: 1 alive, 0 free
};
static_assert(sizeof(GpuParticle) == 48);

struct GpuEmitter {
    glm::vec4 startColor{0.0f};  // linear HDR RGB, alpha
    glm::vec4 endColor{0.0f};
    glm::vec4 size{0.0f};    // x: width at birth (m); y: width at death; z: lifetime (s); w: coverage
                             // (0: adds light, fire and sparks; 1: covers what is behind, smoke)
    glm::vec4 motion{0.0f};  // x: spin (rad/s); y: 1 = the chapter's unclamped age (alpha below 0);
                             // z: 1 = textured sprite, 0 = a soft dot
    glm::uvec4 ring{0u};     // x: first slot in the pool; y: slots; z: the oldest slot (next written)
};
static_assert(sizeof(GpuEmitter) == 80);

}  // namespace fx
