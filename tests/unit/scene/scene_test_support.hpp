#pragma once
// Shared by the scene tests: where the fixtures are, and loading them with the test asset root.
#include <filesystem>
#include <string>
#include "base/paths.hpp"

#include "base/file_io.hpp"
#include "scene/scene_loader.hpp"

namespace scene_test {

inline std::filesystem::path dataDir() {
    return std::filesystem::path(FXLAB_TEST_DATA) / "scenes";
}
inline std::filesystem::path resDir() {
    return fx::projectRoot() / "res";
}

// Test scenes may use files under tests/data.
inline fx::SceneLoadOptions testOptions(bool checkFiles = true) {
    fx::SceneLoadOptions options;
    options.assetRoot = FXLAB_TEST_DATA;
    options.checkFilesExist = checkFiles;
    return options;
}

inline std::string readFixture(const std::string& name) {
    auto text = fx::readTextFile(dataDir() / name);
    return text ? *text : std::string();
}

inline bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace scene_test
