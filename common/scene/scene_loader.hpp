#pragma once
// Loading scene files. A bad file is refused with one message that names the file, the field (as a JSON
// path such as objects[2].material.emissive[1], or line:column for a syntax error) and the reason; the
// loader never throws and never crashes on input. Oddities that do not stop the scene (unknown fields,
// fields a light type does not use) come back as warnings in Scene::warnings and are logged.
#include <filesystem>
#include <string_view>

#include "base/result.hpp"
#include "scene/scene.hpp"

namespace fx {

// <repo>/res, or $FXLAB_ROOT/res when that variable is set (how lessons find res/ at run time).
std::filesystem::path defaultAssetRoot();

struct SceneLoadOptions {
    // Paths in the scene resolve relative to the scene file and must stay under this folder.
    std::filesystem::path assetRoot = defaultAssetRoot();
    // Refuse a scene whose glTF files or textures do not exist. Off for scenes whose assets a tool
    // generates later.
    bool checkFilesExist = true;
    // With checkFilesExist: read every glTF model the scene names and check the clips objects ask for,
    // refusing a scene whose model cannot load (with the model's path and the reason). Off where only
    // the scene text matters.
    bool loadModels = true;
};

Result<Scene> loadScene(const std::filesystem::path& file, const SceneLoadOptions& options = {});

// Parses `json` as if it had been read from `nominalFile`: messages name it and relative paths resolve
// against its folder.
Result<Scene> parseScene(std::string_view json, const std::filesystem::path& nominalFile,
                         const SceneLoadOptions& options = {});

}  // namespace fx
