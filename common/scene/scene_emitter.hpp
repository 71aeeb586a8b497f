#pragma once
// Particle emitters: camera-facing sprites that rise, grow or shrink, spin, and change colour over their
// life. The kind says how a particle blends: fire and sparks add light (order does not matter), smoke
// covers what is behind it (alpha blending).
#include <string>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scene/asset_ref.hpp"

namespace fx {

enum class EmitterKind { fire, smoke, sparks };

struct ParticleEmitter {
    std::string name;
    EmitterKind kind = EmitterKind::fire;
    glm::vec3 position{0.0f};
    float ratePerSecond = 5.0f;
    float lifetimeSeconds = 1.0f;
    float startSize = 0.5f;                        // sprite width (m) when born
    float endSize = 0.1f;                          // sprite width (m) when it dies
    glm::vec4 startColor{4.0f, 1.6f, 0.4f, 1.0f};  // linear HDR RGB, alpha in [0, 1]
    glm::vec4 endColor{1.0f, 0.15f, 0.05f, 0.0f};
    float riseSpeed = 1.0f;             // m/s upwards
    float spinDegreesPerSecond = 0.0f;  // sprite rotation about the view axis (the chapter's exercise: 120)
    float spread = 0.0f;  // m/s: random sideways speed at birth (0: straight up, as the chapter)
    AssetRef sprite;      // empty: a soft round dot
    int seed = 1;         // fixed seed, so headless runs repeat exactly

    bool operator==(const ParticleEmitter&) const = default;
};

}  // namespace fx
