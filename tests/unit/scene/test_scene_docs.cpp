// docs/scene-format.md shows the every-field fixture and the smallest scene; they must stay true.
#include "base/paths.hpp"
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/file_io.hpp"
#include "scene/scene_loader.hpp"
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

}  // namespace
