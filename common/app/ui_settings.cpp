#include "app/ui_settings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "base/file_io.hpp"
#include "base/log.hpp"
#include "base/user_folders.hpp"
#include "base/utf8_path.hpp"

namespace fx {

namespace fs = std::filesystem;

namespace {

constexpr FileLimit kSettingsLimit{"settings file", 64 * 1024};

std::optional<fs::path> fromEnvironment(const char* name) {
    const char* value = std::getenv(name);
    if (!value || !*value) return std::nullopt;
    return pathFromUtf8(value);
}

Result<float> number(const nlohmann::json& j, const char* field, const std::string& source, float fallback) {
    if (!j.contains(field)) return fallback;
    const nlohmann::json& v = j.at(field);
    if (!v.is_number()) return Error{cat(source, ": ", field, ": expected a number, got ", v.dump())};
    double d = v.get<double>();
    if (!std::isfinite(d)) return Error{cat(source, ": ", field, ": expected a finite number")};
    return float(d);
}

}  // namespace

float clampTextScale(float scale) {
    if (!std::isfinite(scale)) return 1.0f;
    // Onto the quarter steps, so that + and - always land on the same values.
    return std::clamp(std::round(scale / kTextScaleStep) * kTextScaleStep, kMinTextScale, kMaxTextScale);
}

fs::path uiSettingsPath() {
    if (auto dir = fromEnvironment("FXLAB_CONFIG_DIR")) return *dir / "ui.json";
    if (auto dir = userConfigFolder()) return *dir / "fxlab" / "ui.json";
    return fs::path("out") / "ui.json";
}

Result<UiSettings> parseUiSettings(const std::string& text, const std::string& source) {
    nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) return Error{cat(source, ": not a JSON object")};
    UiSettings s;
    auto scale = number(j, "textScale", source, s.textScale);
    if (!scale) return Error{scale.error()};
    s.textScale = clampTextScale(*scale);
    if (j.contains("window")) {
        const nlohmann::json& w = j.at("window");
        if (!w.is_array() || w.size() != 2 || !w[0].is_number_integer() || !w[1].is_number_integer())
            return Error{cat(source, ": window: expected [width, height], got ", w.dump())};
        int width = w[0].get<int>(), height = w[1].get<int>();
        // A window of a few pixels is one nobody could use again: it is not restored.
        if (width >= 200 && height >= 150 && width <= 16384 && height <= 16384)
            s.windowSize = Size2D{width, height};
    }
    const char* fields[] = {"columnShare", "lessonShare", "pictureShare"};
    float* shares[] = {&s.shares.column, &s.shares.lesson, &s.shares.picture};
    for (int i = 0; i < 3; ++i) {
        auto v = number(j, fields[i], source, *shares[i]);
        if (!v) return Error{v.error()};
        *shares[i] = *v;
    }
    s.shares = clampShares(s.shares);
    return s;
}

std::string uiSettingsJson(const UiSettings& s) {
    nlohmann::json j;
    j["textScale"] = s.textScale;
    if (s.windowSize) j["window"] = {s.windowSize->width, s.windowSize->height};
    j["columnShare"] = s.shares.column;
    j["lessonShare"] = s.shares.lesson;
    j["pictureShare"] = s.shares.picture;
    return j.dump(2) + "\n";
}

UiSettings loadUiSettings(const fs::path& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) return {};
    auto text = readFile(path, kSettingsLimit);
    if (!text) {
        log::warning(text.error(), "; using the default layout");
        return {};
    }
    auto parsed = parseUiSettings(*text, path.string());
    if (!parsed) {
        log::warning(parsed.error(), "; using the default layout");
        return {};
    }
    return *parsed;
}

Status saveUiSettings(const fs::path& path, const UiSettings& settings) {
    return writeFileAtomically(path, uiSettingsJson(settings));
}

}  // namespace fx
