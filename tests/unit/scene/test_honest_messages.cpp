// Refusals that say what they mean: a value and its limit never print alike when they differ, a key
// holding a NUL is shown whole (escaped), and a model without clips reads as a sentence.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "scene/scene_loader.hpp"
#include "scene_test_support.hpp"

namespace {

using nlohmann::json;
using scene_test::contains;

std::filesystem::path nominalFile() {
    return scene_test::dataDir() / "patched_every_field.json";
}

fx::Result<fx::Scene> parsePatched(const char* patch) {
    json base = json::parse(scene_test::readFixture("every_field.json"));
    return fx::parseScene(base.patch(json::parse(patch)).dump(2), nominalFile(), scene_test::testOptions());
}

}  // namespace

TEST(HonestMessages, AValueThatRoundsToItsLimitShowsBothExactly) {
    // Before: "camera.fovY: 180 becomes 180 as a float ... out of range (0, 180)".
    auto scene = parsePatched(
        R"([{"op":"remove","path":"/camera/lens"},{"op":"add","path":"/camera/fovY","value":179.99999999}])");
    ASSERT_FALSE(scene.ok());
    EXPECT_TRUE(contains(scene.error(), "camera.fovY: 179.99999999 becomes 180 as a float")) << scene.error();
    EXPECT_TRUE(contains(scene.error(), "out of range (0, 180)")) << scene.error();
}

TEST(HonestMessages, AnIntegerJustPastItsLimitShowsBothWhole) {
    // Before: "emitters[0].seed: 2.14748e+09 is out of range [0, 2.14748e+09]".
    auto scene = parsePatched(R"([{"op":"replace","path":"/emitters/0/seed","value":2147483648}])");
    ASSERT_FALSE(scene.ok());
    EXPECT_TRUE(contains(scene.error(), "emitters[0].seed: 2147483648 is out of range [0, 2147483647]"))
        << scene.error();
}

TEST(HonestMessages, AKeyHoldingANulIsShownWholeWithTheNulEscaped) {
    // Before: the warning ended at the NUL ("vers").
    json base = json::parse(scene_test::readFixture("every_field.json"));
    std::string text = base.dump(2);
    text.insert(text.find('{') + 1, "\n  \"vers\\u0000ion\": 1,");
    auto scene = fx::parseScene(text, nominalFile(), scene_test::testOptions());
    ASSERT_TRUE(scene.ok()) << scene.error();
    bool found = false;
    for (const std::string& w : scene->warnings) {
        EXPECT_EQ(w.find('\0'), std::string::npos) << w;
        if (contains(w, "vers\\u0000ion: unknown field")) found = true;
    }
    EXPECT_TRUE(found);
}

TEST(HonestMessages, AModelWithoutClipsIsNamedInASentence) {
    // Before: "objects[0].animation.clip: ../models/crate.gltf the file has no animation clips".
    const std::string text =
        R"({"name": "a crate that walks", "camera": {"position": [0, 2, 8], "target": [0, 0, 0]}, "objects": [{"name": "crate", "gltf": "../models/crate.gltf",
        "animation": {"clip": "walk"}}]})";
    fx::SceneLoadOptions options;
    options.assetRoot = scene_test::resDir();
    auto scene = fx::parseScene(text, scene_test::resDir() / "scenes" / "crate_walks.json", options);
    ASSERT_FALSE(scene.ok());
    EXPECT_TRUE(
        contains(scene.error(), "objects[0].animation.clip: ../models/crate.gltf has no animation clips"))
        << scene.error();
}
