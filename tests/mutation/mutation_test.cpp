// The mutation test: every shipped scene (res/scenes/*.json) and every generated glTF model
// (res/models/*.gltf), broken in thousands of deterministic ways (json_mutations.hpp) and loaded by the
// loaders with no GL. Each mutant must load or be refused with a message that names the file; none may
// crash, throw or hang (CTest's timeout), and under the sanitizer build none may read out of bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/file_io.hpp"
#include "base/log.hpp"
#include "json_mutations.hpp"
#include "scene/gltf_loader.hpp"
#include "scene/scene_loader.hpp"

namespace {

namespace fs = std::filesystem;

fs::path resDir() {
    return FXLAB_RES_DIR;
}

std::vector<fs::path> filesIn(const fs::path& folder, const std::string& extension) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.path().extension() == extension) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

// What a run saw, for the summary line and the failure messages.
struct Tally {
    int loaded = 0, refused = 0;
    std::vector<std::string> problems;

    void check(const std::string& what, bool ok, const std::string& error, const std::string& fileName) {
        if (ok) {
            ++loaded;
            return;
        }
        ++refused;
        if (error.find(fileName) == std::string::npos && problems.size() < 20)
            problems.push_back(what + ": the refusal does not name " + fileName + ": " +
                               error.substr(0, 300));
    }
};

std::string readWhole(const fs::path& file) {
    auto text = fx::readTextFile(file);
    EXPECT_TRUE(text.ok()) << text.error();
    return text.ok() ? *text : std::string();
}

TEST(Mutation, ShippedScenesSurviveEveryMutation) {
    fx::log::setConsoleLevel(fx::log::Level::error);  // thousands of warnings say nothing here
    auto start = std::chrono::steady_clock::now();
    auto scenes = filesIn(resDir() / "scenes", ".json");
    ASSERT_GE(scenes.size(), 6u);
    fx::SceneLoadOptions options;
    options.assetRoot = resDir();
    Tally tally;
    for (const fs::path& file : scenes) {
        std::string text = readWhole(file);
        auto original = fx::parseScene(text, file, options);
        ASSERT_TRUE(original.ok()) << original.error();
        std::vector<mutation::Mutant> mutants = mutation::treeMutations(nlohmann::json::parse(text), 3);
        auto more = mutation::textMutations(text, 48, 24);
        mutants.insert(mutants.end(), more.begin(), more.end());
        for (const auto& mutant : mutants) {
            auto scene = fx::parseScene(mutant.text, file, options);
            tally.check(file.filename().string() + ": " + mutant.what, scene.ok(),
                        scene.ok() ? "" : scene.error(), file.filename().string());
        }
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("scenes: %d mutants loaded, %d refused, in %.2f s\n", tally.loaded, tally.refused, seconds);
    EXPECT_GT(tally.refused, 1000);  // the mutations do break things
    for (const auto& problem : tally.problems) ADD_FAILURE() << problem;
}

TEST(Mutation, GeneratedModelsSurviveEveryMutation) {
    fx::log::setConsoleLevel(fx::log::Level::error);
    auto start = std::chrono::steady_clock::now();
    auto models = filesIn(resDir() / "models", ".gltf");
    ASSERT_GE(models.size(), 4u);
    Tally tally;
    for (const fs::path& file : models) {
        std::string text = readWhole(file);
        std::string name = file.filename().string();
        auto original = fx::parseGltf(text, file.parent_path(), file);
        ASSERT_TRUE(original.ok()) << original.error();
        nlohmann::json document = nlohmann::json::parse(text);
        std::vector<mutation::Mutant> mutants = mutation::gltfMutations(document);
        auto tree = mutation::treeMutations(document, 1);
        // Every fourth tree mutation: the models are large, and the targeted ones above cover the sizes.
        for (std::size_t i = 0; i < tree.size(); i += 4) mutants.push_back(tree[i]);
        auto more = mutation::textMutations(text, 24, 8);
        mutants.insert(mutants.end(), more.begin(), more.end());
        for (const auto& mutant : mutants) {
            auto model = fx::parseGltf(mutant.text, file.parent_path(), file);
            tally.check(name + ": " + mutant.what, model.ok(), model.ok() ? "" : model.error(), name);
        }
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("models: %d mutants loaded, %d refused, in %.2f s\n", tally.loaded, tally.refused, seconds);
    EXPECT_GT(tally.refused, 500);
    for (const auto& problem : tally.problems) ADD_FAILURE() << problem;
}

}  // namespace
