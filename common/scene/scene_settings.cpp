#include "scene/scene_settings.hpp"

#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>

#include "base/log.hpp"
#include "scene/scene_enums.hpp"
#include "scene/scene_post.hpp"

namespace fx {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A setting and how to read its value off a scene (nothing when the scene does not have it).
struct Declared {
    SettingSpec spec;
    std::function<std::optional<std::string>(const Scene&)> value;
};

SettingSpec number(std::string path, double min, double max, double fallback, double sliderMin,
                   double sliderMax, std::string unit, std::string help) {
    SettingSpec s;
    s.path = std::move(path);
    s.min = min;
    s.max = max;
    s.defaultValue = fallback;
    s.sliderMin = sliderMin;
    s.sliderMax = sliderMax;
    s.unit = std::move(unit);
    s.help = std::move(help);
    return s;
}

SettingSpec aboveZero(SettingSpec s) {
    s.minOpen = true;
    return s;
}

SettingSpec required(SettingSpec s) {
    s.required = true;
    return s;
}

SettingSpec integer(std::string path, int min, int max, int fallback, int sliderMax, std::string help) {
    SettingSpec s = number(std::move(path), min, max, fallback, min, sliderMax, {}, std::move(help));
    s.type = ParamType::Int;
    return s;
}

template <class E>
SettingSpec names(std::string path, E fallback, std::string help) {
    SettingSpec s;
    s.path = std::move(path);
    s.type = ParamType::Choice;
    for (const auto& entry : enumNames(E{})) s.choices.emplace_back(entry.name);
    s.min = 0;
    s.max = s.sliderMax = double(s.choices.size() - 1);
    s.defaultValue = double(static_cast<int>(fallback));
    s.help = std::move(help);
    return s;
}

// A value as a parameter takes it.
std::string text(float v) {
    return settingNumberText(v);
}
std::string text(int v) {
    return std::to_string(v);
}
template <class E>
std::string name(E v) {
    return std::string(enumName(v));
}

// Reads `field` of `section` when the scene has the section.
template <class Section, class Get>
auto from(Section section, Get get) {
    return [section, get](const Scene& scene) -> std::optional<std::string> {
        const auto* s = section(scene);
        if (!s) return std::nullopt;
        return get(*s);
    };
}

const BloomSettings* bloom(const Scene& s) {
    return s.postEffects.bloom ? &*s.postEffects.bloom : nullptr;
}
const ColorMatrixSettings* colorMatrix(const Scene& s) {
    return s.postEffects.colorMatrix ? &*s.postEffects.colorMatrix : nullptr;
}
const RadialBlurSettings* radialBlur(const Scene& s) {
    return s.postEffects.radialBlur ? &*s.postEffects.radialBlur : nullptr;
}
const DepthOfFieldSettings* depthOfField(const Scene& s) {
    return s.postEffects.depthOfField ? &*s.postEffects.depthOfField : nullptr;
}
const ToneMapSettings* toneMap(const Scene& s) {
    return s.postEffects.toneMap ? &*s.postEffects.toneMap : nullptr;
}
const Lens* lens(const Scene& s) {
    return s.camera.lens ? &*s.camera.lens : nullptr;
}
const CloudLayer* firstCloud(const Scene& s) {
    return s.clouds.empty() ? nullptr : &s.clouds.front();
}

// The settings, in the order of docs/scene-format.md's table. The defaults are the scene structs' own
// (scene_post.hpp, scene_camera.hpp, scene_cloud.hpp), so a file that leaves a field out gets the same.
const std::vector<Declared>& declared() {
    static const BloomSettings b;
    static const ColorMatrixSettings m;
    static const RadialBlurSettings r;
    static const DepthOfFieldSettings d;
    static const ToneMapSettings t;
    static const Lens l;
    static const CloudLayer c;
    static const std::vector<Declared> table = {
        {number("postEffects.bloom.threshold", 0, 1e4, b.threshold, 0, 16, {},
                "brightness (the largest channel) where blooming starts"),
         from(bloom, [](const BloomSettings& s) { return text(s.threshold); })},
        {number("postEffects.bloom.knee", 0, 1, b.knee, 0, 1, {},
                "soft-knee width as a fraction of the threshold (0: a hard cut)"),
         from(bloom, [](const BloomSettings& s) { return text(s.knee); })},
        {number("postEffects.bloom.intensity", 0, 100, b.intensity, 0, 4, {},
                "scale of the light added back"),
         from(bloom, [](const BloomSettings& s) { return text(s.intensity); })},
        // As many levels as the chain makes (effects/bloom/bloom_levels.hpp: kBloomMaxLevels, which
        // effects/bloom/bloom_chain.cpp checks against this table).
        {integer("postEffects.bloom.levels", 1, 8, b.levels, 8, "levels in the blur chain"),
         from(bloom, [](const BloomSettings& s) { return text(s.levels); })},
        {required(
             names("postEffects.colorMatrix.preset", m.preset,
                   "the transform: the chapter's two filters, or the affine negative no 3x3 matrix makes")),
         from(colorMatrix, [](const ColorMatrixSettings& s) { return name(s.preset); })},
        {number("postEffects.colorMatrix.amount", 0, 1, m.amount, 0, 1, {},
                "blend from the original (0) to the full matrix (1)"),
         from(colorMatrix, [](const ColorMatrixSettings& s) { return text(s.amount); })},
        {number(
             "postEffects.radialBlur.center[0]", -5, 5, r.center.x, -5, 5, {},
             "the blur's centre, x in texture coordinates of the screen (0 left, 1 right; outside: off screen)"),
         from(radialBlur, [](const RadialBlurSettings& s) { return text(s.center.x); })},
        {number(
             "postEffects.radialBlur.center[1]", -5, 5, r.center.y, -5, 5, {},
             "the blur's centre, y in texture coordinates of the screen (0 bottom, 1 top; outside: off screen)"),
         from(radialBlur, [](const RadialBlurSettings& s) { return text(s.center.y); })},
        {number(
             "postEffects.radialBlur.length", 0, 1, r.length, 0, 0.2, {},
             "the chapter's z: tap spacing per unit of distance to the centre (above 1/7 the far taps overshoot the centre)"),
         from(radialBlur, [](const RadialBlurSettings& s) { return text(s.length); })},
        {number("postEffects.radialBlur.start", 0, 2, r.start, 0, 2, {},
                "the chapter's w: distance from the centre that stays sharp (texture coordinates)"),
         from(radialBlur, [](const RadialBlurSettings& s) { return text(s.start); })},
        // As many taps as the blur takes (effects/post/radial_blur.hpp: kRadialBlurMaxSamples).
        {integer("postEffects.radialBlur.taps", 1, 256, r.taps, 256, "taps per pixel"),
         from(radialBlur, [](const RadialBlurSettings& s) { return text(s.taps); })},
        {number("postEffects.depthOfField.maxCoc", 0, 256, d.maxCocPixels, 0, 256, "px",
                "largest circle of confusion, diameter in pixels; larger ones are clamped"),
         from(depthOfField, [](const DepthOfFieldSettings& s) { return text(s.maxCocPixels); })},
        {integer("postEffects.depthOfField.taps", 1, 128, d.taps, 128,
                 "taps of the ring kernel (16, 22, 43 or 71; others round down)"),
         from(depthOfField, [](const DepthOfFieldSettings& s) { return text(s.taps); })},
        {names("postEffects.toneMap.operator", t.curve,
               "the output's tone curve (clip: none, values above 1 clip, as in the chapters)"),
         from(toneMap, [](const ToneMapSettings& s) { return name(s.curve); })},
        {aboveZero(number("postEffects.toneMap.exposure", 0, 1000, t.exposure, 0.01, 16, {},
                          "multiplies the HDR colour before the tone curve")),
         from(toneMap, [](const ToneMapSettings& s) { return text(s.exposure); })},
        {required(aboveZero(
             number("camera.lens.focalLength", 0, 2000, l.focalLengthMm, 0, 2000, "mm", "focal length"))),
         from(lens, [](const Lens& s) { return text(s.focalLengthMm); })},
        {aboveZero(number("camera.lens.sensorWidth", 0, 100, l.sensorWidthMm, 1, 100, "mm", "sensor width")),
         from(lens, [](const Lens& s) { return text(s.sensorWidthMm); })},
        {required(aboveZero(number("camera.lens.fNumber", 0, 64, l.fNumber, 0, 32, {},
                                   "f-number N: the aperture is the focal length / N"))),
         from(lens, [](const Lens& s) { return text(s.fNumber); })},
        {required(aboveZero(
             number("camera.lens.focusDistance", 0, kInfinity, l.focusDistanceM, 0, 300, "m",
                    "focus distance, more than 0.1% beyond the focal length (a far mountain: infinity)"))),
         from(lens, [](const Lens& s) { return text(s.focusDistanceM); })},
        {required(number("clouds[0].bottom", -1e4, 1e5, c.bottom, -100, 1000, "m",
                         "height of the slab's lower face; below top")),
         from(firstCloud, [](const CloudLayer& s) { return text(s.bottom); })},
        {required(number("clouds[0].top", -1e4, 1e5, c.top, -100, 1000, "m",
                         "height of the slab's upper face; at or below bottom: no cloud")),
         from(firstCloud, [](const CloudLayer& s) { return text(s.top); })},
        {aboveZero(number("clouds[0].noise[0].scale", 0, 100, c.noise[0].scale, 0.0001, 1, "1/m",
                          "texture repeats per metre, layer 0 (the chapter: 1/311)")),
         from(firstCloud, [](const CloudLayer& s) { return text(s.noise[0].scale); })},
        {aboveZero(number("clouds[0].noise[1].scale", 0, 100, c.noise[1].scale, 0.0001, 1, "1/m",
                          "texture repeats per metre, layer 1 (the chapter: 1/127)")),
         from(firstCloud, [](const CloudLayer& s) { return text(s.noise[1].scale); })},
        {number("clouds[0].threshold", 0, 1, c.threshold, 0, 1, {},
                "density at or below it is clear sky (1: no cloud at all)"),
         from(firstCloud, [](const CloudLayer& s) { return text(s.threshold); })},
        // As many samples as the march takes (effects/clouds/cloud_march.hpp: kCloudMaxSteps).
        {integer("clouds[0].steps", 0, 512, c.steps, 512,
                 "samples along each ray through the slab (0: no cloud)"),
         from(firstCloud, [](const CloudLayer& s) { return text(s.steps); })},
    };
    return table;
}

}  // namespace

const std::vector<SettingSpec>& sceneSettingSpecs() {
    static const std::vector<SettingSpec> specs = [] {
        std::vector<SettingSpec> out;
        for (const Declared& d : declared()) out.push_back(d.spec);
        return out;
    }();
    return specs;
}

const SettingSpec& sceneSetting(std::string_view path) {
    for (const SettingSpec& s : sceneSettingSpecs())
        if (s.path == path) return s;
    log::error("no scene setting \"", path, "\" (scene/scene_settings.cpp lists them)");
    std::abort();
}

std::vector<SettingText> sceneSettings(const Scene& scene) {
    std::vector<SettingText> out;
    for (const Declared& d : declared())
        if (auto value = d.value(scene)) out.push_back({d.spec.path, *value});
    return out;
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
    for (const SettingSpec& s : sceneSettingSpecs()) paths.push_back(s.path);
    return paths;
}

std::vector<const SettingSpec*> settingsUnder(std::string_view prefix) {
    std::vector<const SettingSpec*> out;
    for (const SettingSpec& s : sceneSettingSpecs())
        if (s.path.starts_with(prefix)) out.push_back(&s);
    return out;
}

std::string settingField(const SettingSpec& setting, std::string_view prefix) {
    return setting.path.substr(prefix.size());
}

std::string settingsTableMarkdown() {
    std::string out = "| Setting | Default | Values | Unit | What it is |\n|---|---|---|---|---|\n";
    for (const SettingSpec& s : sceneSettingSpecs()) {
        std::string fallback = s.required ? "**required**" : cat("`", s.valueText(s.defaultValue), "`");
        std::string values = s.type == ParamType::Choice
                                 ? s.rangeText()
                                 : cat(s.type == ParamType::Int ? "whole numbers in " : "", s.rangeText());
        out += cat("| `", s.path, "` | ", fallback, " | ", values, " | ", s.unit, " | ", s.help, " |\n");
    }
    return out;
}

}  // namespace fx
