#include "effects/post/fullscreen_variants.hpp"

#include "base/log.hpp"

namespace fx {

FullscreenVariants::FullscreenVariants(std::string fragmentShader, std::string label, std::string defines)
    : shader_(std::move(fragmentShader)),
      label_(std::move(label)),
      defines_(std::move(defines)),
      built_(std::make_unique<std::map<std::string, FullscreenPass>>()) {}

std::string shaderDefines(std::initializer_list<ShaderChoice> choices) {
    std::string lines;
    for (const auto& [name, value] : choices) lines += cat("#define ", name, " ", value, "\n");
    return lines;
}

const FullscreenPass& FullscreenVariants::get(std::initializer_list<ShaderChoice> choices) const {
    std::string key;
    for (const auto& [name, value] : choices) key += cat(key.empty() ? "" : ", ", name, " ", value);
    auto found = built_->find(key);
    if (found != built_->end()) return found->second;
    std::string label = key.empty() ? label_ : cat(label_, " (", key, ")");
    return built_->emplace(key, FullscreenPass(shader_, label, defines_ + shaderDefines(choices)))
        .first->second;
}

}  // namespace fx
