#pragma once
// A scene's settings that start a lesson's parameters, by their path in the scene file, as text a
// parameter takes (Param::fromScene("camera.lens.fNumber")): the post effects it asks for
// (postEffectSettings, scene_post.hpp), the camera's physical lens and the first cloud layer. The
// runner applies them before a preset and the command line, so each value shows where it came from.
#include <optional>
#include <string>
#include <vector>

#include "base/params.hpp"
#include "scene/scene.hpp"

namespace fx {

// Every setting of `scene` a parameter may start from.
std::vector<SettingText> sceneSettings(const Scene& scene);
// Every path sceneSettings can name, whether this scene has the setting or not.
std::vector<std::string> sceneSettingPaths();
// Every setting at the value a scene file that leaves the field out gets.
std::vector<SettingText> sceneSettingDefaults();

// The parts: {"camera.lens.focalLength", "50"}...; {"clouds[0].bottom", "0"}, {"clouds[0].steps", "8"}...
std::vector<SettingText> cameraLensSettings(const std::optional<Lens>& lens);
std::vector<SettingText> cloudLayerSettings(const std::vector<CloudLayer>& clouds);

}  // namespace fx
