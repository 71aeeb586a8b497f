// The settings a teacher finds again at the next start: text scale, window size, layout shares.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

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

// Issue 40, defect 2: a settings file that cannot be read was replaced by the defaults at exit.
TEST(UiSettings, AFileThatCannotBeReadIsNeverWrittenOver) {
    const fs::path dir = fs::temp_directory_path() / ("fxlab-ui-kept-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string big(1 << 20, ' ');
    const std::vector<std::pair<std::string, std::string>> damaged = {
        {"syntax", "{\"textScale\": 1.5,\n  \"window\": [1280 720]}\n"},
        {"big", "{\"textScale\": 1.5" + big + "}"},
        {"byte", "{\"textScale\": 1.5, \"x\": \"\xff\"}"},
        {"type", "{\"textScale\": \"big\"}"},
        {"array", "[1, 2]"},
    };
    fx::UiSettings changed;
    changed.textScale = 2.0f;
    for (const auto& [name, text] : damaged) {
        const fs::path file = dir / (name + ".json");
        ASSERT_TRUE(fx::writeFileAtomically(file, std::string_view(text)));
        EXPECT_EQ(fx::loadUiSettings(file), fx::UiSettings{}) << name;  // the defaults, in memory
        ASSERT_TRUE(fx::whyUiSettingsAreKept(file)) << name;
        auto first = fx::saveUiSettings(file, changed);
        ASSERT_FALSE(first) << name;
        EXPECT_NE(first.error().find("kept as it is"), std::string::npos) << first.error();
        EXPECT_TRUE(fx::saveUiSettings(file, changed)) << name;  // said once a run, not at every change
        EXPECT_EQ(*fx::readFile(file, {"settings", 4 << 20}), text) << name;  // byte for byte
    }
    // A syntax error is placed by line and column.
    EXPECT_NE(fx::whyUiSettingsAreKept(dir / "syntax.json")->find("syntax.json:2:"), std::string::npos)
        << *fx::whyUiSettingsAreKept(dir / "syntax.json");

    // A read-only file is the teacher's choice: the rename would replace it all the same.
    const fs::path locked = dir / "locked.json";
    ASSERT_TRUE(fx::saveUiSettings(locked, fx::UiSettings{}));
    const std::string before = *fx::readTextFile(locked);
    fs::permissions(locked, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
    EXPECT_FALSE(fx::saveUiSettings(locked, changed));  // by its mode, so even as root
    EXPECT_EQ(*fx::readTextFile(locked), before);
    // A good file is written as before.
    const fs::path good = dir / "good.json";
    ASSERT_TRUE(fx::saveUiSettings(good, fx::UiSettings{}));
    ASSERT_TRUE(fx::saveUiSettings(good, changed));
    EXPECT_EQ(fx::loadUiSettings(good), changed);
    fs::remove_all(dir);
}
