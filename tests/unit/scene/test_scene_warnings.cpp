// Things the loader accepts but reports: unknown fields (with a suggestion), fields the object's type does
// not use, repeated names. Warnings come back in the scene and go to the log.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "base/log.hpp"
#include "scene/scene_loader.hpp"
#include "scene_test_support.hpp"

namespace {

using scene_test::contains;

bool hasWarning(const fx::Scene& scene, const std::string& expected) {
    return std::find(scene.warnings.begin(), scene.warnings.end(), expected) != scene.warnings.end();
}

std::string allWarnings(const fx::Scene& scene) {
    std::string text;
    for (const auto& warning : scene.warnings) text += "\n  " + warning;
    return text;
}

TEST(SceneWarnings, UnknownFieldsAreNamedWithSuggestions) {
    auto scene = fx::loadScene(scene_test::dataDir() / "unknown_fields.json", scene_test::testOptions());
    ASSERT_TRUE(scene.ok()) << scene.error();
    EXPECT_EQ(scene->warnings.size(), 6u) << allWarnings(*scene);
    EXPECT_TRUE(hasWarning(*scene, "camera.fov: unknown field, ignored (did you mean \"fovY\"?)"))
        << allWarnings(*scene);
    EXPECT_TRUE(hasWarning(
        *scene, "objects[0].material.emisive: unknown field, ignored (did you mean \"emissive\"?)"))
        << allWarnings(*scene);
    EXPECT_TRUE(hasWarning(*scene, "objects[0].material.shininess: unknown field, ignored"))
        << allWarnings(*scene);
    EXPECT_TRUE(
        hasWarning(*scene, "postEffects.blom: unknown post effect, ignored (did you mean \"bloom\"?)"))
        << allWarnings(*scene);
    EXPECT_TRUE(hasWarning(*scene, "postEffects.vignette: unknown post effect, ignored"))
        << allWarnings(*scene);
    EXPECT_TRUE(hasWarning(*scene, "author: unknown field, ignored")) << allWarnings(*scene);
    // The misspelt field did not take effect, and the unknown effects were not requested.
    EXPECT_EQ(scene->objects.at(0).material.emissive, glm::vec3(0.0f));
    EXPECT_FALSE(scene->postEffects.bloom.has_value());
}

TEST(SceneWarnings, AreLoggedWithTheFileName) {
    std::vector<std::string> logged;
    int sink = fx::log::addSink([&](fx::log::Level level, std::string_view message) {
        if (level == fx::log::Level::warning) logged.emplace_back(message);
    });
    auto file = scene_test::dataDir() / "unknown_fields.json";
    auto scene = fx::loadScene(file, scene_test::testOptions());
    fx::log::removeSink(sink);
    ASSERT_TRUE(scene.ok()) << scene.error();
    ASSERT_EQ(logged.size(), scene->warnings.size());
    bool found = std::any_of(logged.begin(), logged.end(), [&](const std::string& line) {
        return line ==
               file.string() +
                   ": objects[0].material.emisive: unknown field, ignored (did you mean \"emissive\"?)";
    });
    EXPECT_TRUE(found);
}

TEST(SceneWarnings, FieldsTheTypeDoesNotUse) {
    const char* text = R"({
      "name": "unused fields",
      "camera": {"position": [0, 2, 8], "target": [0, 0, 0]},
      "lights": [
        {"type": "point", "position": [0, 3, 0], "innerCone": 10, "shadow": {"casts": true}},
        {"type": "directional", "direction": [0, -1, 0], "radius": 4}
      ],
      "objects": [
        {"primitive": {"shape": "sphere", "size": [1, 1, 1]}, "motion": {"type": "bob", "radius": 2}}
      ]
    })";
    auto scene = fx::parseScene(text, scene_test::dataDir() / "inline.json", scene_test::testOptions());
    ASSERT_TRUE(scene.ok()) << scene.error();
    EXPECT_TRUE(
        hasWarning(*scene, "lights[0].shadow: ignored: only directional lights cast shadows in fxlab"))
        << allWarnings(*scene);
    EXPECT_TRUE(hasWarning(*scene, "lights[0].innerCone: ignored: not used by a point light"))
        << allWarnings(*scene);
    EXPECT_TRUE(hasWarning(*scene, "lights[1].radius: ignored: not used by a directional light"))
        << allWarnings(*scene);
    EXPECT_TRUE(hasWarning(*scene, "objects[0].primitive.size: ignored: not used by a sphere"))
        << allWarnings(*scene);
    EXPECT_TRUE(hasWarning(*scene, "objects[0].motion.radius: ignored: not used by a \"bob\" motion"))
        << allWarnings(*scene);
    EXPECT_EQ(scene->warnings.size(), 5u) << allWarnings(*scene);
    EXPECT_FALSE(scene->lights[0].castsShadows());
}

TEST(SceneWarnings, RepeatedObjectNamesAndPoorDepthRange) {
    const char* text = R"({
      "name": "repeats",
      "camera": {"position": [0, 2, 8], "target": [0, 0, 0], "near": 0.001, "far": 1000},
      "objects": [
        {"name": "crate", "primitive": {"shape": "box"}},
        {"name": "crate", "primitive": {"shape": "box"}}
      ]
    })";
    auto scene = fx::parseScene(text, scene_test::dataDir() / "inline.json", scene_test::testOptions());
    ASSERT_TRUE(scene.ok()) << scene.error();
    EXPECT_TRUE(hasWarning(*scene, "objects[1].name: another object is already called \"crate\""))
        << allWarnings(*scene);
    EXPECT_TRUE(std::any_of(scene->warnings.begin(), scene->warnings.end(), [](const std::string& w) {
        return w.rfind("camera.far: far / near = 1e+06", 0) == 0;
    })) << allWarnings(*scene);
}

TEST(SceneWarnings, ValidSceneHasNone) {
    auto scene = fx::loadScene(scene_test::dataDir() / "every_field.json", scene_test::testOptions());
    ASSERT_TRUE(scene.ok()) << scene.error();
    EXPECT_TRUE(scene->warnings.empty()) << allWarnings(*scene);
}

}  // namespace
