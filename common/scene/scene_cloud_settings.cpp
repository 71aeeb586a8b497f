#include "scene/scene_cloud_settings.hpp"

#include "scene/scene_post.hpp"

namespace fx {

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

std::vector<std::string> cloudLayerSettingPaths() {
    std::vector<std::string> paths;
    for (SettingText& s : cloudLayerSettings({CloudLayer{}})) paths.push_back(std::move(s.setting));
    return paths;
}

}  // namespace fx
