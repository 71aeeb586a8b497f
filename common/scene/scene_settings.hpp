#pragma once
// A scene's settings that start a lesson's parameters, each declared once (sceneSettingSpecs()): its
// path in the scene file, the values it may take, its default, its unit and its help. The scene reader
// checks the file with these ranges and defaults (readSetting), the writer writes them, the runner
// hands the scene's values to the parameters that start from them, a lesson's parameter takes its
// range, slider and help from them (ParamSet::addSetting), and docs/scene-format.md's settings table
// is theirs (the unit test SceneSettingsDocs compares the two). The ranges are the physical ones: a
// focus distance may be infinity (written "infinity" in a file), a scene may light as many point lights
// as the GPU list holds.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/params.hpp"
#include "scene/scene.hpp"

namespace fx {

const std::vector<SettingSpec>& sceneSettingSpecs();
// The setting at `path` ("postEffects.bloom.threshold"). A path no scene file has is a mistake in the
// code that asks for it: the program stops with the path.
const SettingSpec& sceneSetting(std::string_view path);

// Every setting of `scene` a parameter may start from (those of the effects it asks for, its lens and
// its first cloud layer), as the text a parameter takes: {"postEffects.bloom.threshold", "1"}.
std::vector<SettingText> sceneSettings(const Scene& scene);
// Every path sceneSettings can name, whether this scene has the setting or not.
std::vector<std::string> sceneSettingPaths();
// Every setting at the value a scene file that leaves the field out gets.
std::vector<SettingText> sceneSettingDefaults();

// The settings whose path starts with `prefix` ("postEffects.bloom."), in the table's order.
std::vector<const SettingSpec*> settingsUnder(std::string_view prefix);
// The setting's last path part ("threshold", "center[0]", "noise[1].scale" for "clouds[0].noise[1].scale").
std::string settingField(const SettingSpec& setting, std::string_view prefix);

// docs/scene-format.md's table of these settings, as markdown (the docs test compares it).
std::string settingsTableMarkdown();

}  // namespace fx
