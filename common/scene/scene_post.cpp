#include "scene/scene_post.hpp"

#include <charconv>
#include <cmath>

namespace fx {

std::string settingNumberText(float value) {
    if (std::isinf(value)) return value > 0 ? "infinity" : "-infinity";
    char text[32];
    auto [end, error] = std::to_chars(text, text + sizeof text, value);
    return error == std::errc() ? std::string(text, end) : std::string("nan");
}

}  // namespace fx
