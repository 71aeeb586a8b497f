#pragma once
// The first cloud layer's settings by their path in the scene file, as text a lesson parameter takes
// (Param::fromScene("clouds[0].threshold")): {"clouds[0].bottom", "0"}, {"clouds[0].steps", "8"}...
// Like postEffectSettings (scene_post.hpp), for the fields a lesson may change live.
#include <string>
#include <vector>

#include "base/params.hpp"
#include "scene/scene_cloud.hpp"

namespace fx {

std::vector<SettingText> cloudLayerSettings(const std::vector<CloudLayer>& clouds);
// Every path cloudLayerSettings can name.
std::vector<std::string> cloudLayerSettingPaths();

}  // namespace fx
