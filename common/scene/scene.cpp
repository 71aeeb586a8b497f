#include "scene/scene.hpp"

#include <algorithm>

namespace fx {

bool PostEffects::wants(PostEffect effect) const {
    switch (effect) {
        case PostEffect::bloom:
            return bloom.has_value();
        case PostEffect::colorMatrix:
            return colorMatrix.has_value();
        case PostEffect::radialBlur:
            return radialBlur.has_value();
        case PostEffect::depthOfField:
            return depthOfField.has_value();
        case PostEffect::toneMap:
            return toneMap.has_value();
    }
    return false;
}

std::vector<Light> allLights(const Scene& scene) {
    std::vector<Light> lights = scene.lights;
    for (const LightGrid& grid : scene.lightGrids) {
        std::vector<Light> generated = expandLightGrid(grid);
        lights.insert(lights.end(), generated.begin(), generated.end());
    }
    return lights;
}

std::vector<std::filesystem::path> referencedFiles(const Scene& scene) {
    std::vector<std::filesystem::path> files;
    auto add = [&](const AssetRef& asset) {
        if (!asset.empty()) files.push_back(asset.resolved);
    };
    for (const auto& object : scene.objects) {
        add(object.gltf);
        add(object.material.baseColorTexture);
    }
    for (const auto& emitter : scene.emitters) add(emitter.sprite);
    for (const auto& cloud : scene.clouds) add(cloud.densityTexture);
    std::sort(files.begin(), files.end());
    files.erase(std::unique(files.begin(), files.end()), files.end());
    return files;
}

}  // namespace fx
