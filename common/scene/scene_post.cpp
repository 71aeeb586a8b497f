#include "scene/scene_post.hpp"

#include <charconv>

#include "base/log.hpp"
#include "scene/scene_enums.hpp"

namespace fx {
namespace {

// Collects one effect's settings under "postEffects.<effect>.".
class SettingList {
public:
    SettingList(std::vector<SettingText>& out, PostEffect effect)
        : out_(out), prefix_(cat("postEffects.", enumName(effect), ".")) {}
    void number(std::string_view field, float value) { add(field, settingNumberText(value)); }
    void integer(std::string_view field, int value) { add(field, std::to_string(value)); }
    template <class E>
    void name(std::string_view field, E value) {
        add(field, std::string(enumName(value)));
    }

private:
    void add(std::string_view field, std::string text) {
        out_.push_back({prefix_ + std::string(field), std::move(text)});
    }
    std::vector<SettingText>& out_;
    std::string prefix_;
};

}  // namespace

std::string settingNumberText(float value) {
    char text[32];
    auto [end, error] = std::to_chars(text, text + sizeof text, value);
    return error == std::errc() ? std::string(text, end) : std::string("nan");
}

std::vector<SettingText> postEffectSettings(const PostEffects& post) {
    std::vector<SettingText> out;
    if (const auto& bloom = post.bloom) {
        SettingList s(out, PostEffect::bloom);
        s.number("threshold", bloom->threshold);
        s.number("knee", bloom->knee);
        s.number("intensity", bloom->intensity);
        s.integer("levels", bloom->levels);
    }
    if (const auto& matrix = post.colorMatrix) {
        SettingList s(out, PostEffect::colorMatrix);
        s.name("preset", matrix->preset);
        s.number("amount", matrix->amount);
    }
    if (const auto& blur = post.radialBlur) {
        SettingList s(out, PostEffect::radialBlur);
        s.number("center[0]", blur->center.x);
        s.number("center[1]", blur->center.y);
        s.number("length", blur->length);
        s.number("start", blur->start);
        s.integer("taps", blur->taps);
    }
    if (const auto& dof = post.depthOfField) {
        SettingList s(out, PostEffect::depthOfField);
        s.number("maxCoc", dof->maxCocPixels);
        s.integer("taps", dof->taps);
    }
    if (const auto& toneMap = post.toneMap) {
        SettingList s(out, PostEffect::toneMap);
        s.name("operator", toneMap->curve);
        s.number("exposure", toneMap->exposure);
    }
    return out;
}

std::vector<std::string> postEffectSettingPaths() {
    // Every effect present with its defaults names every path once.
    PostEffects all{BloomSettings{}, ColorMatrixSettings{}, RadialBlurSettings{}, DepthOfFieldSettings{},
                    ToneMapSettings{}};
    std::vector<std::string> paths;
    for (SettingText& s : postEffectSettings(all)) paths.push_back(std::move(s.setting));
    return paths;
}

}  // namespace fx
