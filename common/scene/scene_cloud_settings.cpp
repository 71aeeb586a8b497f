#include "scene/scene_cloud_settings.hpp"

#include <charconv>

namespace fx {
namespace {

// The shortest text that reads back as the same float.
std::string shortest(float value) {
    char text[32];
    auto [end, error] = std::to_chars(text, text + sizeof text, value);
    return error == std::errc() ? std::string(text, end) : std::string("nan");
}

}  // namespace

std::vector<SettingText> cloudLayerSettings(const std::vector<CloudLayer>& clouds) {
    if (clouds.empty()) return {};
    const CloudLayer& c = clouds.front();
    return {
        {"clouds[0].bottom", shortest(c.bottom)},
        {"clouds[0].top", shortest(c.top)},
        {"clouds[0].noise[0].scale", shortest(c.noise[0].scale)},
        {"clouds[0].noise[1].scale", shortest(c.noise[1].scale)},
        {"clouds[0].threshold", shortest(c.threshold)},
        {"clouds[0].steps", std::to_string(c.steps)},
    };
}

std::vector<std::string> cloudLayerSettingPaths() {
    std::vector<std::string> paths;
    for (SettingText& s : cloudLayerSettings({CloudLayer{}})) paths.push_back(std::move(s.setting));
    return paths;
}

}  // namespace fx
