// Asset paths: relative to the scene file, never outside the asset root, and checked for existence when
// asked.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>

#include "base/file_io.hpp"
#include "scene/asset_path.hpp"
#include "scene/scene_loader.hpp"
#include "scene_test_support.hpp"

namespace {

namespace fs = std::filesystem;
using scene_test::contains;

TEST(ScenePaths, EscapeFromTheAssetRootIsRefused) {
    auto file = scene_test::dataDir() / "escape_path.json";
    auto scene =
        fx::loadScene(file, scene_test::testOptions(false));  // refused even without the existence check
    ASSERT_FALSE(scene.ok());
    EXPECT_TRUE(contains(scene.error(), file.string() + ": objects[0].material.baseColorTexture: "))
        << scene.error();
    EXPECT_TRUE(contains(scene.error(), "resolves to /etc/passwd")) << scene.error();
    EXPECT_TRUE(contains(scene.error(), "outside the asset root")) << scene.error();
}

TEST(ScenePaths, MissingFileNamesTheResolvedPath) {
    auto file = scene_test::dataDir() / "missing_texture.json";
    auto scene = fx::loadScene(file, scene_test::testOptions());
    ASSERT_FALSE(scene.ok());
    const auto resolved = (fs::weakly_canonical(scene_test::dataDir()) / "assets" / "not_there.png").string();
    EXPECT_TRUE(contains(scene.error(), file.string() + ": objects[1].material.baseColorTexture: "))
        << scene.error();
    EXPECT_TRUE(contains(scene.error(), "file not found: " + resolved)) << scene.error();
    EXPECT_TRUE(contains(scene.error(), "written as \"assets/../assets/not_there.png\"")) << scene.error();

    // Without the check the scene loads and keeps both spellings.
    auto unchecked = fx::loadScene(file, scene_test::testOptions(false));
    ASSERT_TRUE(unchecked.ok()) << unchecked.error();
    EXPECT_EQ(unchecked->objects[1].material.baseColorTexture.path, "assets/../assets/not_there.png");
    EXPECT_EQ(unchecked->objects[1].material.baseColorTexture.resolved, fs::path(resolved));
}

class AssetRootFixture : public ::testing::Test {
protected:
    void SetUp() override {
        // One folder per test and process: ctest runs tests of this fixture in parallel.
        root_ = fs::temp_directory_path() /
                ("fx_scene_paths_" +
                 std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
                 std::to_string(::getpid()));
        fs::remove_all(root_);
        fs::create_directories(root_ / "scenes");
        fs::create_directories(root_ / "textures");
        ASSERT_TRUE(fx::writeFileAtomically(root_ / "textures" / "a.png", std::string_view("x")).ok());
    }
    void TearDown() override { fs::remove_all(root_); }

    fs::path root_;
};

TEST_F(AssetRootFixture, ResolvesRelativeToTheSceneFolder) {
    auto resolved = fx::resolveAssetPath("../textures/a.png", root_ / "scenes", root_);
    ASSERT_TRUE(resolved.ok()) << resolved.error();
    EXPECT_EQ(*resolved, fs::weakly_canonical(root_ / "textures" / "a.png"));
}

TEST_F(AssetRootFixture, AbsolutePathInsideTheRootIsAccepted) {
    auto resolved = fx::resolveAssetPath((root_ / "textures" / "a.png").string(), root_ / "scenes", root_);
    ASSERT_TRUE(resolved.ok()) << resolved.error();
}

TEST_F(AssetRootFixture, AbsoluteOrDottedPathsOutsideAreRefused) {
    EXPECT_FALSE(fx::resolveAssetPath("/etc/passwd", root_ / "scenes", root_).ok());
    EXPECT_FALSE(fx::resolveAssetPath("../../etc/passwd", root_ / "scenes", root_).ok());
    // A sibling folder whose name starts like the root's is still outside it.
    fs::create_directories(root_.string() + "_sibling");
    EXPECT_FALSE(
        fx::resolveAssetPath("../../" + root_.filename().string() + "_sibling/a.png", root_ / "scenes", root_)
            .ok());
    fs::remove_all(root_.string() + "_sibling");
    // Neither the root folder itself nor an empty path names a file.
    EXPECT_FALSE(fx::resolveAssetPath("..", root_ / "scenes", root_).ok());
    EXPECT_FALSE(fx::resolveAssetPath("", root_ / "scenes", root_).ok());
}

TEST_F(AssetRootFixture, SymbolicLinkOutOfTheRootIsRefused) {
    std::error_code ec;
    fs::create_directory_symlink("/etc", root_ / "textures" / "outside", ec);
    if (ec) GTEST_SKIP() << "cannot make a symbolic link here: " << ec.message();
    auto resolved = fx::resolveAssetPath("../textures/outside/passwd", root_ / "scenes", root_);
    ASSERT_FALSE(resolved.ok());
    EXPECT_TRUE(contains(resolved.error(), "resolves to /etc/passwd")) << resolved.error();
}

}  // namespace
