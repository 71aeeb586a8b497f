// docs/scene-format.md shows the every-field fixture and the smallest scene, the limits and the settings
// that start lessons' parameters; they must stay true.
#include <gtest/gtest.h>
#include "base/paths.hpp"

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/file_io.hpp"
#include "base/message_text.hpp"
#include "scene/scene_limits.hpp"
#include "scene/scene_loader.hpp"
#include "scene/scene_settings.hpp"
#include "scene_test_support.hpp"

namespace {

std::vector<std::string> jsonBlocks(const std::string& markdown) {
    std::vector<std::string> blocks;
    const std::string open = "```json\n", close = "```";
    for (auto at = markdown.find(open); at != std::string::npos; at = markdown.find(open, at)) {
        at += open.size();
        auto end = markdown.find(close, at);
        if (end == std::string::npos) break;
        blocks.push_back(markdown.substr(at, end - at));
        at = end + close.size();
    }
    return blocks;
}

TEST(SceneDocs, ExamplesMatchTheFixturesAndLoad) {
    auto markdown = fx::readTextFile(fx::projectRoot() / "docs" / "scene-format.md");
    ASSERT_TRUE(markdown.ok()) << markdown.error();
    auto blocks = jsonBlocks(*markdown);
    ASSERT_GE(blocks.size(), 2u);
    EXPECT_EQ(nlohmann::json::parse(blocks[0]),
              nlohmann::json::parse(scene_test::readFixture("every_field.json")));
    for (const auto& block : blocks) {
        auto scene =
            fx::parseScene(block, scene_test::dataDir() / "from_docs.json", scene_test::testOptions());
        EXPECT_TRUE(scene.ok()) << scene.error();
        if (scene.ok()) {
            EXPECT_TRUE(scene->warnings.empty());
        }
    }
}

TEST(SceneDocs, TheLimitsTableMatchesTheCode) {
    auto markdown = fx::readTextFile(fx::projectRoot() / "docs" / "scene-format.md");
    ASSERT_TRUE(markdown.ok()) << markdown.error();
    namespace limits = fx::scene_limits;
    auto row = [](const std::string& what, const std::string& value) {
        return "| " + what + " | " + value + " |";
    };
    const std::string rows[] = {
        row("scene file size", fx::describeByteCount(fx::file_limits::scene.maxBytes)),
        row("`objects`", std::to_string(limits::kMaxObjects)),
        row("`lights`", std::to_string(limits::kMaxLights)),
        row("`lightGrids`", std::to_string(limits::kMaxLightGrids) + " (and " +
                                std::to_string(fx::kMaxGridLights) +
                                " point lights from them and `lights` together)"),
        row("`emitters`", std::to_string(limits::kMaxEmitters)),
        row("`clouds`", std::to_string(limits::kMaxClouds)),
        row("clips named by one object", std::to_string(limits::kMaxClipsPerObject)),
        row("any string (names, descriptions, paths, field names)",
            std::to_string(limits::kMaxStringBytes) + " bytes"),
        row("nesting of objects and arrays", std::to_string(limits::kMaxNesting) + " levels"),
        row("vertices of glTF models over all objects (each object draws its own copy)",
            std::to_string(limits::kMaxDrawnVertices) + " (2^23)"),
        row("glTF file, its `.bin` buffers and images",
            fx::describeByteCount(fx::file_limits::gltf.maxBytes) + " each"),
        row("PNG texture", fx::describeByteCount(fx::file_limits::png.maxBytes)),
    };
    for (const std::string& expected : rows)
        EXPECT_NE(markdown->find(expected), std::string::npos) << expected;
    EXPECT_NE(markdown->find("Messages quote at most " + std::to_string(fx::kExcerptBytes) + " bytes"),
              std::string::npos);
}

// The settings table is the declarations' (scene/scene_settings.cpp): a range or a default changed in
// one place and not the other fails here.
TEST(SceneDocs, TheSettingsTableIsTheDeclarations) {
    auto markdown = fx::readTextFile(fx::projectRoot() / "docs" / "scene-format.md");
    ASSERT_TRUE(markdown.ok()) << markdown.error();
    const std::string expected = fx::settingsTableMarkdown();
    EXPECT_NE(markdown->find(expected), std::string::npos)
        << "docs/scene-format.md's settings table is not scene/scene_settings.cpp's; it reads:\n"
        << expected;
}

}  // namespace
