// JSON syntax errors carry the file, line and column.
#include <gtest/gtest.h>

#include "scene/scene_loader.hpp"
#include "scene_test_support.hpp"

namespace {

using scene_test::contains;

std::string syntaxError(const std::string& text) {
    auto scene = fx::parseScene(text, "/scenes/typed.json", scene_test::testOptions());
    return scene.ok() ? std::string("(accepted)") : scene.error();
}

TEST(SceneSyntax, KnownFileGivesExactLineAndColumn) {
    // Line 9 is `    {"primitive": {"shape": "sphere"} "material": {}}`: a comma is missing before the
    // string that starts in column 39.
    auto file = scene_test::dataDir() / "syntax_error.json";
    auto scene = fx::loadScene(file, scene_test::testOptions());
    ASSERT_FALSE(scene.ok());
    EXPECT_TRUE(contains(scene.error(), file.string() + ":9:39: JSON syntax error: ")) << scene.error();
    EXPECT_TRUE(contains(scene.error(), "unexpected string literal; expected '}'")) << scene.error();
    EXPECT_FALSE(contains(scene.error(), "[json.exception"))
        << "nlohmann's prefix should be gone: " << scene.error();
}

TEST(SceneSyntax, PointsAtTheUnexpectedToken) {
    EXPECT_TRUE(contains(syntaxError("{\n  \"name\": \"a\",\n  \"camera\": [1 22]\n}"), "typed.json:3:16: "));
    EXPECT_TRUE(contains(syntaxError("{\"name\": \"a\",}"), "typed.json:1:14: "));  // trailing comma
}

TEST(SceneSyntax, PointsAtTheBadCharacter) {
    // An unescaped line break inside a string: the break itself, at the end of line 1.
    EXPECT_TRUE(contains(syntaxError("{\"name\": \"a\nb\"}"), "typed.json:1:12: "));
    EXPECT_TRUE(contains(syntaxError("{\"name\": tru}"), "typed.json:1:13: "));
}

TEST(SceneSyntax, UnexpectedEndOfInput) {
    std::string message = syntaxError("{\n  \"name\": \"a\",\n  \"lights\": [");
    EXPECT_TRUE(contains(message, "typed.json:3:14: ")) << message;
    EXPECT_TRUE(contains(message, "end of input")) << message;
    EXPECT_TRUE(contains(syntaxError(""), "typed.json:1:1: ")) << syntaxError("");
}

TEST(SceneSyntax, ColumnsCountCharactersNotBytes) {
    // "é" is two bytes in UTF-8; the stray 7 is still in column 14.
    EXPECT_TRUE(contains(syntaxError("{\"name\": \"\xC3\xA9\" 7}"), "typed.json:1:14: "));
}

}  // namespace
