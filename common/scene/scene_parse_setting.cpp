// Reads the settings that start lessons' parameters with the ranges scene/scene_settings.cpp declares.
#include <cmath>
#include <limits>

#include "scene/scene_parse.hpp"
#include "scene/scene_settings.hpp"

namespace fx {

NumberRange settingRange(std::string_view path) {
    const SettingSpec& s = sceneSetting(path);
    const double largest = double(std::numeric_limits<float>::max());
    return NumberRange{std::isinf(s.min) ? -largest : s.min, std::isinf(s.max) ? largest : s.max, s.minOpen,
                       false};
}

float readSetting(JsonFieldReader& reader, std::string_view key, std::string_view path, float fallback) {
    const SettingSpec& s = sceneSetting(path);
    if (std::isinf(s.max) && reader.has(key)) {
        const nlohmann::json& value = reader.required(key);
        if (value.is_string() && value.get_ref<const std::string&>() == "infinity")
            return std::numeric_limits<float>::infinity();
    }
    return s.required ? reader.requiredNumber(key, settingRange(path))
                      : reader.number(key, fallback, settingRange(path));
}

int readIntegerSetting(JsonFieldReader& reader, std::string_view key, std::string_view path, int fallback) {
    return reader.integer(key, fallback, settingRange(path));
}

}  // namespace fx
