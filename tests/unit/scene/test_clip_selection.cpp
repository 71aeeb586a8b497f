// Playing one, several or all of a glTF file's clips (scene "animation.clip"), and the message for a
// name the file does not have.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "scene/clip_selection.hpp"
#include "scene/gltf_loader.hpp"
#include "scene/scene_writer.hpp"
#include "scene_test_support.hpp"

namespace {

// tests/data/scenes/assets/robot.gltf: "walk" moves node 0, "wave" scales node 1, both 1 s long.
fx::GltfModel robot() {
    auto model = fx::loadGltf(scene_test::dataDir() / "assets" / "robot.gltf");
    EXPECT_TRUE(model.ok()) << model.error();
    return model.ok() ? std::move(*model) : fx::GltfModel{};
}

fx::Animation playing(std::vector<std::string> clips) {
    fx::Animation animation;
    animation.clips = std::move(clips);
    return animation;
}

}  // namespace

TEST(ClipSelection, OneClipByName) {
    auto clip = fx::selectClips(robot(), playing({"wave"}));
    ASSERT_TRUE(clip.ok()) << clip.error();
    EXPECT_EQ(clip->name, "wave");
    ASSERT_EQ(clip->channels.size(), 1u);
    EXPECT_EQ(clip->channels[0].node, 1);
}

TEST(ClipSelection, SeveralOrAllClipsPlayTogether) {
    for (const auto& names : {std::vector<std::string>{"walk", "wave"}, std::vector<std::string>{"*"}}) {
        auto clip = fx::selectClips(robot(), playing(names));
        ASSERT_TRUE(clip.ok()) << clip.error();
        EXPECT_EQ(clip->name, "walk + wave");
        ASSERT_EQ(clip->channels.size(), 2u);
        EXPECT_FLOAT_EQ(clip->duration, 1.0f);
        // Both nodes move in one pose.
        std::vector<fx::NodeTransform> pose(2);
        fx::applyClip(*clip, 1.0f, pose);
        EXPECT_EQ(pose[0].translation, glm::vec3(0, 0, 1));
        EXPECT_EQ(pose[1].scale, glm::vec3(1, 2, 1));
    }
}

TEST(ClipSelection, AMissingClipListsTheFilesClipsAndTheNearestName) {
    auto clip = fx::selectClips(robot(), playing({"wav"}));
    ASSERT_FALSE(clip.ok());
    EXPECT_EQ(clip.error(), "has no clip \"wav\" (did you mean \"wave\"?); its clips: walk, wave");
    auto none = fx::selectClips(fx::GltfModel{}, playing({"walk"}));
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.error(), "has no animation clips");
}

TEST(ClipSelection, SceneFilesNameSeveralClipsAsAListOrAllAsAStar) {
    const std::pair<const char*, std::vector<std::string>> cases[] = {
        {R"(["walk", "wave"])", {"walk", "wave"}}, {R"("*")", {"*"}}};
    for (const auto& [clip, expected] : cases) {
        SCOPED_TRACE(clip);
        std::string text =
            std::string(R"({"name": "clips", "camera": {"position": [0, 1, 4], "target": [0, 0, 0]},
            "objects": [{"gltf": "assets/robot.gltf", "animation": {"clip": )") +
            clip + "}}]}";
        auto scene = fx::parseScene(text, scene_test::dataDir() / "clips.json", scene_test::testOptions());
        ASSERT_TRUE(scene.ok()) << scene.error();
        EXPECT_EQ(scene->objects[0].animation.clips, expected);
        EXPECT_TRUE(scene->objects[0].skinned);
        // Written back the way it was written.
        auto again = fx::parseScene(fx::saveScene(*scene), scene_test::dataDir() / "clips.json",
                                    scene_test::testOptions());
        ASSERT_TRUE(again.ok()) << again.error();
        EXPECT_EQ(again->objects[0].animation, scene->objects[0].animation);
    }
}
