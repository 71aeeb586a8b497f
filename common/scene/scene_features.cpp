#include "scene/scene_features.hpp"

#include "base/log.hpp"
#include "scene/scene_enums.hpp"

namespace fx {

SceneFeatures features(const Scene& scene) {
    SceneFeatures result;
    result.lights = static_cast<int>(scene.lights.size());
    for (const auto& grid : scene.lightGrids) result.lights += grid.lightCount();
    for (const auto& light : scene.lights)
        if (light.castsShadows()) ++result.shadowCastingLights;
    for (const auto& object : scene.objects) {
        if (object.skinned) ++result.skinnedMeshes;
        if (object.moves()) ++result.movingObjects;
        if (object.mirror) ++result.mirrors;
        glm::vec3 emitted = object.material.emitted();
        if (emitted.r > 1.0f || emitted.g > 1.0f || emitted.b > 1.0f) ++result.hdrEmissiveObjects;
    }
    result.particleEmitters = static_cast<int>(scene.emitters.size());
    result.cloudLayers = static_cast<int>(scene.clouds.size());
    result.physicalLens = scene.camera.lens.has_value();
    result.postEffects = scene.postEffects;
    return result;
}

bool SceneFeatures::has(SceneFeature feature) const {
    switch (feature) {
        case SceneFeature::skinnedMeshes:
            return skinnedMeshes > 0;
        case SceneFeature::shadows:
            return shadowCastingLights > 0;
        case SceneFeature::particles:
            return particleEmitters > 0;
        case SceneFeature::clouds:
            return cloudLayers > 0;
        case SceneFeature::hdrEmissive:
            return hdrEmissiveObjects > 0;
        case SceneFeature::physicalLens:
            return physicalLens;
        case SceneFeature::manyLights:
            return lights > kManyLightsAbove;
        case SceneFeature::movingObjects:
            return movingObjects > 0;
        case SceneFeature::bloom:
            return postEffects.wants(PostEffect::bloom);
        case SceneFeature::colorMatrix:
            return postEffects.wants(PostEffect::colorMatrix);
        case SceneFeature::radialBlur:
            return postEffects.wants(PostEffect::radialBlur);
        case SceneFeature::depthOfField:
            return postEffects.wants(PostEffect::depthOfField);
        case SceneFeature::toneMap:
            return postEffects.wants(PostEffect::toneMap);
        case SceneFeature::mirror:
            return mirrors > 0;
    }
    return false;
}

std::string SceneFeatures::missingReason(SceneFeature feature) const {
    if (has(feature)) return {};
    auto notRequested = [](PostEffect effect) {
        return cat("scene does not ask for ", enumName(effect), " (no postEffects.", enumName(effect), ")");
    };
    switch (feature) {
        case SceneFeature::skinnedMeshes:
            return "scene has no skinned mesh (no object with a glTF file and an animation clip)";
        case SceneFeature::shadows:
            return "scene has no light that casts shadows";
        case SceneFeature::particles:
            return "scene has no particle emitter";
        case SceneFeature::clouds:
            return "scene has no cloud layer";
        case SceneFeature::hdrEmissive:
            return "scene has no HDR emissive object (no emissive colour x strength above 1)";
        case SceneFeature::physicalLens:
            return "camera has no physical lens (it uses fovY)";
        case SceneFeature::manyLights:
            return cat("scene has ", lights, " light", lights == 1 ? "" : "s",
                       "; many lights means more than ", kManyLightsAbove);
        case SceneFeature::movingObjects:
            return "scene has no moving object";
        case SceneFeature::bloom:
            return notRequested(PostEffect::bloom);
        case SceneFeature::colorMatrix:
            return notRequested(PostEffect::colorMatrix);
        case SceneFeature::radialBlur:
            return notRequested(PostEffect::radialBlur);
        case SceneFeature::depthOfField:
            return notRequested(PostEffect::depthOfField);
        case SceneFeature::toneMap:
            return notRequested(PostEffect::toneMap);
        case SceneFeature::mirror:
            return "scene has no mirror (no object with \"mirror\")";
    }
    return {};
}

}  // namespace fx
