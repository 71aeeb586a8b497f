// The settings a teacher finds again at the next start: text scale, window size, layout shares.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "app/ui_settings.hpp"
#include "base/file_io.hpp"
#include "base/user_folders.hpp"

namespace fs = std::filesystem;

TEST(UiSettings, RoundTripThroughTheFile) {
    const fs::path dir = fs::temp_directory_path() / "fxlab-ui-settings-test";
    fs::remove_all(dir);
    fx::UiSettings s;
    s.textScale = 1.75f;
    s.windowSize = fx::Size2D{1920, 1080};
    s.shares = {0.35f, 0.5f, 0.6f};
    ASSERT_TRUE(fx::saveUiSettings(dir / "ui.json", s));
    EXPECT_EQ(fx::loadUiSettings(dir / "ui.json"), s);
    fs::remove_all(dir);
}

TEST(UiSettings, AMissingOrDamagedFileGivesTheDefaults) {
    EXPECT_EQ(fx::loadUiSettings("/nonexistent/fxlab/ui.json"), fx::UiSettings{});
    auto bad = fx::parseUiSettings(R"({"textScale": "big"})", "ui.json");
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error(), "ui.json: textScale: expected a number, got \"big\"");
    auto window = fx::parseUiSettings(R"({"window": [1280]})", "ui.json");
    ASSERT_FALSE(window);
    EXPECT_NE(window.error().find("ui.json: window: expected [width, height]"), std::string::npos);
    EXPECT_FALSE(fx::parseUiSettings("[", "ui.json"));
}

TEST(UiSettings, TextScaleStaysOnItsSteps) {
    EXPECT_EQ(fx::clampTextScale(1.3f), 1.25f);
    EXPECT_EQ(fx::clampTextScale(100.0f), fx::kMaxTextScale);
    EXPECT_EQ(fx::clampTextScale(0.0f), fx::kMinTextScale);
    EXPECT_EQ(fx::clampTextScale(std::numeric_limits<float>::infinity()), 1.0f);
    // A window of a few pixels is not restored.
    auto tiny = fx::parseUiSettings(R"({"window": [1, 1], "textScale": 9})", "ui.json");
    ASSERT_TRUE(tiny);
    EXPECT_FALSE(tiny->windowSize);
    EXPECT_EQ(tiny->textScale, fx::kMaxTextScale);
}

namespace {
// Sets an environment variable, or removes it (nullptr).
void setVariable(const char* name, const char* value) {
#ifdef _WIN32
    _putenv_s(name, value ? value : "");  // an empty value removes it
#else
    if (value)
        setenv(name, value, 1);
    else
        unsetenv(name);
#endif
}
}  // namespace

TEST(UiSettings, TheFileIsUnderTheConfigFolder) {
    setVariable("FXLAB_CONFIG_DIR", "/tmp/a");
    EXPECT_EQ(fx::uiSettingsPath(), fs::path("/tmp/a/ui.json"));
    setVariable("FXLAB_CONFIG_DIR", nullptr);
#ifdef _WIN32
    // Windows: %APPDATA%\fxlab (base/user_folders_win.cpp).
    ASSERT_TRUE(fx::userConfigFolder());
    EXPECT_EQ(fx::uiSettingsPath(), *fx::userConfigFolder() / "fxlab" / "ui.json");
#else
    setVariable("XDG_CONFIG_HOME", "/tmp/b");
    EXPECT_EQ(fx::uiSettingsPath(), fs::path("/tmp/b/fxlab/ui.json"));
    setVariable("XDG_CONFIG_HOME", nullptr);
#endif
}
