#pragma once
// What a scene calls for. Lessons build only the passes and simulations whose feature is present, and
// show the reason string for the ones they skip ("scene has no particle emitter").
#include <string>

#include "scene/scene.hpp"

namespace fx {

enum class SceneFeature {
    skinnedMeshes,  // skinning work, skinned shadow pass
    shadows,        // shadow-map pass
    particles,      // particle update and particle pass
    clouds,         // cloud pass
    hdrEmissive,    // something bright enough for bloom to find without lights
    physicalLens,   // circle of confusion from the lens
    manyLights,     // light loops that want culling or deferred shading
    movingObjects,  // per-frame transform updates
    bloom,          // the post effects the scene asks for
    colorMatrix,
    radialBlur,
    depthOfField,
    toneMap,
    mirror,  // a planar reflection pass (an object with "mirror")
};

// A scene with more lights than this has "many lights".
inline constexpr int kManyLightsAbove = 4;

struct SceneFeatures {
    int skinnedMeshes = 0;  // objects with a glTF file and an animation clip
    int shadowCastingLights = 0;
    int particleEmitters = 0;
    int cloudLayers = 0;
    int hdrEmissiveObjects = 0;  // objects whose emissive colour x strength has a component above 1
    int movingObjects = 0;       // objects with a motion
    int lights = 0;
    int mirrors = 0;  // objects with a mirror (at most one)
    bool physicalLens = false;
    PostEffects postEffects;  // which effects are requested, with their settings

    bool has(SceneFeature feature) const;
    // Why `feature` is absent, e.g. "scene has no particle emitter"; empty when it is present.
    std::string missingReason(SceneFeature feature) const;
};

SceneFeatures features(const Scene& scene);

}  // namespace fx
