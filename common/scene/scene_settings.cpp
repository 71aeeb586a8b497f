#include "scene/scene_settings.hpp"

#include "scene/scene_post.hpp"

namespace fx {

std::vector<SettingText> cameraLensSettings(const std::optional<Lens>& lens) {
    if (!lens) return {};
    return {
        {"camera.lens.focalLength", settingNumberText(lens->focalLengthMm)},
        {"camera.lens.sensorWidth", settingNumberText(lens->sensorWidthMm)},
        {"camera.lens.fNumber", settingNumberText(lens->fNumber)},
        {"camera.lens.focusDistance", settingNumberText(lens->focusDistanceM)},
    };
}

std::vector<SettingText> cloudLayerSettings(const std::vector<CloudLayer>& clouds) {
    if (clouds.empty()) return {};
    const CloudLayer& c = clouds.front();
    return {
        {"clouds[0].bottom", settingNumberText(c.bottom)},
        {"clouds[0].top", settingNumberText(c.top)},
        {"clouds[0].noise[0].scale", settingNumberText(c.noise[0].scale)},
        {"clouds[0].noise[1].scale", settingNumberText(c.noise[1].scale)},
        {"clouds[0].threshold", settingNumberText(c.threshold)},
        {"clouds[0].steps", std::to_string(c.steps)},
    };
}

std::vector<SettingText> sceneSettings(const Scene& scene) {
    std::vector<SettingText> settings = postEffectSettings(scene.postEffects);
    for (SettingText& s : cameraLensSettings(scene.camera.lens)) settings.push_back(std::move(s));
    for (SettingText& s : cloudLayerSettings(scene.clouds)) settings.push_back(std::move(s));
    return settings;
}

std::vector<SettingText> sceneSettingDefaults() {
    Scene everything;
    everything.postEffects = {BloomSettings{}, ColorMatrixSettings{}, RadialBlurSettings{},
                              DepthOfFieldSettings{}, ToneMapSettings{}};
    everything.camera.lens = Lens{};
    everything.clouds.push_back(CloudLayer{});
    return sceneSettings(everything);
}

std::vector<std::string> sceneSettingPaths() {
    std::vector<std::string> paths;
    for (SettingText& s : sceneSettingDefaults()) paths.push_back(std::move(s.setting));
    return paths;
}

}  // namespace fx
