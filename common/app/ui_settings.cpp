#include "app/ui_settings.hpp"
#include "base/json_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>

#include <sys/stat.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "base/file_io.hpp"
#include "base/json_document.hpp"
#include "base/log.hpp"
#include "base/user_folders.hpp"
#include "base/utf8_path.hpp"

namespace fx {

namespace fs = std::filesystem;

namespace {

constexpr FileLimit kSettingsLimit{"settings file", 64 * 1024};
constexpr JsonLimits kSettingsDocument{"settings file", 1024, 8};

std::optional<fs::path> fromEnvironment(const char* name) {
    const char* value = std::getenv(name);
    if (!value || !*value) return std::nullopt;
    return pathFromUtf8(value);
}

Result<float> number(const nlohmann::json& j, const char* field, const std::string& source, float fallback) {
    if (!j.contains(field)) return fallback;
    const nlohmann::json& v = j.at(field);
    if (!v.is_number()) return Error{cat(source, ": ", field, ": expected a number, got ", dumpJson(v))};
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
    // The scenes' strict reader: a syntax error comes with its line and column.
    auto document = readJsonDocument(text, source, kSettingsDocument);
    if (!document) return Error{document.error()};
    const nlohmann::json& j = *document;
    if (!j.is_object()) return Error{cat(source, ": expected a JSON object, got ", describeJsonType(j))};
    UiSettings s;
    auto scale = number(j, "textScale", source, s.textScale);
    if (!scale) return Error{scale.error()};
    s.textScale = clampTextScale(*scale);
    if (j.contains("window")) {
        const nlohmann::json& w = j.at("window");
        if (!w.is_array() || w.size() != 2 || !w[0].is_number_integer() || !w[1].is_number_integer())
            return Error{cat(source, ": window: expected [width, height], got ", dumpJson(w))};
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
    return dumpJson(j, 2) + "\n";
}

std::optional<std::string> whyUiSettingsAreKept(const fs::path& path) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) return std::nullopt;  // nothing there: written fresh
    auto text = readFile(path, kSettingsLimit);
    if (!text) return text.error();
    auto parsed = parseUiSettings(*text, path.string());
    if (!parsed) return parsed.error();
    // A file the teacher made read-only stays as it is: the rename would replace it all the same.
    if ((st.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0 || ::access(path.c_str(), W_OK) != 0)
        return cat(path.string(), ": is read-only");
    return std::nullopt;
}

UiSettings loadUiSettings(const fs::path& path) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) return {};
    auto text = readFile(path, kSettingsLimit);
    if (!text) {
        log::warning(text.error(), "; using the default layout and keeping the file as it is");
        return {};
    }
    auto parsed = parseUiSettings(*text, path.string());
    if (!parsed) {
        log::warning(parsed.error(), "; using the default layout and keeping the file as it is");
        return {};
    }
    return *parsed;
}

Status saveUiSettings(const fs::path& path, const UiSettings& settings) {
    // Never over a file that cannot be read back (a syntax error, too big, a wrong type, not a file)
    // or that is read-only: it is the teacher's to mend, and this run's layout lives in memory only.
    if (auto kept = whyUiSettingsAreKept(path)) {
        static std::set<std::string> said;  // one warning a file, not one a change
        if (!said.insert(path.string()).second) return Status::success();
        return Error{cat(*kept, "; kept as it is: this run's layout is not saved")};
    }
    return writeFileAtomically(path, uiSettingsJson(settings));
}

}  // namespace fx
