#pragma once
// What the teacher set up in a window and finds again at the next start: the text scale, the window's
// size and the layout's shares. One small JSON file, written atomically (base/file_io) whenever one of
// them changes and at exit:
//   $FXLAB_CONFIG_DIR/ui.json, else $XDG_CONFIG_HOME/fxlab/ui.json, else ~/.config/fxlab/ui.json,
//   else out/ui.json.
// A missing file gives the defaults; a damaged one (a syntax error, with its line:column; too big; a
// field of the wrong type; not a regular file) or a read-only one gives the defaults in memory and a
// warning naming the file and field, and is never written over: it stays as the teacher left it.
#include <filesystem>
#include <optional>
#include <string>

#include "base/result.hpp"
#include "base/size2d.hpp"
#include "ui/panel_layout.hpp"

namespace fx {

struct UiSettings {
    float textScale = 1.0f;
    std::optional<Size2D> windowSize;  // the last window's size; --size wins over it
    LayoutShares shares;
    bool operator==(const UiSettings&) const = default;
};

// The text scale's steps: 0.75 to 3 in quarters (what + and - move between).
inline constexpr float kMinTextScale = 0.75f, kMaxTextScale = 3.0f, kTextScaleStep = 0.25f;
float clampTextScale(float scale);

std::filesystem::path uiSettingsPath();

// `source` names the file in errors ("ui.json: textScale: expected a number").
Result<UiSettings> parseUiSettings(const std::string& text, const std::string& source);
std::string uiSettingsJson(const UiSettings& settings);

// The defaults when there is no file; a damaged file is logged and gives the defaults.
UiSettings loadUiSettings(const std::filesystem::path& path);
// Why the file at `path` may not be written over (it cannot be read back, or is read-only), or nothing.
std::optional<std::string> whyUiSettingsAreKept(const std::filesystem::path& path);
// Writes the settings, unless whyUiSettingsAreKept: then the file stays, and the first such save
// of a run says why (later ones are quiet).
Status saveUiSettings(const std::filesystem::path& path, const UiSettings& settings);

}  // namespace fx
