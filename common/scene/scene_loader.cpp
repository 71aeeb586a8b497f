#include "scene/scene_loader.hpp"

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "base/file_io.hpp"
#include "base/json_document.hpp"
#include "base/log.hpp"
#include "base/message_text.hpp"
#include "base/paths.hpp"
#include "scene/asset_path.hpp"
#include "scene/clip_selection.hpp"
#include "scene/gltf_loader.hpp"
#include "scene/scene_limits.hpp"
#include "scene/scene_parse.hpp"

namespace fx {
namespace {

namespace fs = std::filesystem;

Scene parseSections(const nlohmann::json& root, const fs::path& file, const SceneLoadOptions& options) {
    Scene scene;
    scene.file = file;
    JsonFieldReader reader(root, "", scene.warnings);
    int version = reader.integer("version", kSceneFormatVersion, NumberRange::closed(0, 1.0e9));
    if (version != kSceneFormatVersion)
        reader.fail("version", cat("unsupported format version ", version, "; this build reads version ",
                                   kSceneFormatVersion));
    scene.name = reader.requiredText("name");
    if (scene.name.empty()) reader.fail("name", "the scene name is empty");
    scene.description = reader.text("description", "");
    scene.background = reader.vec3("background", scene.background, kHdrColorRange);
    scene.ambient = reader.vec3("ambient", scene.ambient, kHdrColorRange);

    auto cameraReader = reader.object("camera");
    scene.camera = parseCamera(cameraReader);

    AssetPathReader assets(file.parent_path(), options.assetRoot, options.checkFilesExist);
    reader.forEachObject("lights", scene_limits::kMaxLights,
                         [&](JsonFieldReader& light) { scene.lights.push_back(parseLight(light)); });
    // The point lights go into one GPU list, whether the scene writes them one by one or as grids.
    int pointLights = int(std::count_if(scene.lights.begin(), scene.lights.end(),
                                        [](const Light& l) { return l.type == LightType::point; }));
    reader.forEachObject("lightGrids", scene_limits::kMaxLightGrids, [&](JsonFieldReader& grid) {
        scene.lightGrids.push_back(parseLightGrid(grid));
        pointLights += scene.lightGrids.back().lightCount();
        if (pointLights > kMaxGridLights)
            grid.fail("count", cat("the scene's point lights and grids make ", pointLights,
                                   " lights together; at most ", kMaxGridLights));
    });
    std::set<std::string> names;
    int mirrors = 0;
    reader.forEachObject("objects", scene_limits::kMaxObjects, [&](JsonFieldReader& object) {
        scene.objects.push_back(parseObject(object, assets));
        // One reflection pass per frame: a second mirror would need a second mirrored camera.
        if (scene.objects.back().mirror && ++mirrors > 1)
            object.fail("mirror", "a scene may have one mirror; another object is one already");
        const std::string& name = scene.objects.back().name;
        // Lessons find objects by name; a repeated name would make that ambiguous.
        if (!name.empty() && !names.insert(name).second)
            object.warn("name", cat("another object is already called \"", excerpt(name), "\""));
    });
    reader.forEachObject("emitters", scene_limits::kMaxEmitters, [&](JsonFieldReader& emitter) {
        scene.emitters.push_back(parseEmitter(emitter, assets));
    });
    reader.forEachObject("clouds", scene_limits::kMaxClouds, [&](JsonFieldReader& cloud) {
        scene.clouds.push_back(parseCloudLayer(cloud, assets));
    });
    if (reader.has("postEffects")) {
        auto postReader = reader.object("postEffects");
        scene.postEffects = parsePostEffects(postReader, scene.camera);
    }
    reader.reportUnknown();
    return scene;
}

// Reads every glTF file the objects name (each file once) and checks the clips they ask for, so that a
// model that cannot load refuses the scene with the model's path and the reason, instead of a run that
// quietly draws without it.
void checkModels(const Scene& scene) {
    std::map<fs::path, GltfModel> models;
    std::size_t vertices = 0;  // over all objects: each draws its own copy
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        if (object.gltf.empty()) continue;
        const std::string where = indexPath("objects", i);
        auto cached = models.find(object.gltf.resolved);
        if (cached == models.end()) {
            auto model = loadGltf(object.gltf.resolved);
            if (!model) failField(fieldPath(where, "gltf"), cat("cannot load the model: ", model.error()));
            for (const std::string& w : model->warnings)
                log::warning(object.gltf.resolved.filename().string(), ": ", w);  // once a file
            cached = models.emplace(object.gltf.resolved, std::move(*model)).first;
        }
        vertices += cached->second.vertexCount();
        if (vertices > scene_limits::kMaxDrawnVertices)
            failField(fieldPath(where, "gltf"),
                      cat("the models of objects[0] to objects[", i, "] have ", vertices,
                          " vertices together (this one ", cached->second.vertexCount(),
                          ", each object its own copy on the GPU); a scene may draw at most ",
                          scene_limits::kMaxDrawnVertices, " (docs/scene-format.md, Limits)"));
        if (object.animation.clips.empty()) continue;
        auto clip = selectClips(cached->second, object.animation);
        if (!clip)
            failField(fieldPath(fieldPath(where, "animation"), "clip"),
                      cat(object.gltf.path, " ", clip.error()));
    }
}

}  // namespace

fs::path defaultAssetRoot() {
    return resourceDir();
}

AssetRef AssetPathReader::optional(JsonFieldReader& object, std::string_view key) const {
    if (!object.has(key)) return {};
    return required(object, key);
}

AssetRef AssetPathReader::required(JsonFieldReader& object, std::string_view key) const {
    AssetRef asset;
    asset.path = object.requiredText(key);
    auto resolved = resolveAssetPath(asset.path, sceneFolder_, assetRoot_);
    if (!resolved) object.fail(key, resolved.error());
    asset.resolved = std::move(*resolved);
    if (checkExists_) {
        std::error_code ec;
        if (!fs::is_regular_file(asset.resolved, ec))
            object.fail(key, cat("file not found: ", asset.resolved.string(), " (written as \"",
                                 excerpt(asset.path), "\")"));
    }
    return asset;
}

Result<Scene> parseScene(std::string_view json, const fs::path& nominalFile,
                         const SceneLoadOptions& options) {
    std::error_code ec;
    fs::path file = fs::absolute(nominalFile, ec).lexically_normal();
    if (ec) file = nominalFile;
    const std::string fileName = file.string();
    try {
        nlohmann::json root =
            parseJsonDocument(json, {"scene", scene_limits::kMaxStringBytes, scene_limits::kMaxNesting});
        Scene scene = parseSections(root, file, options);
        if (options.checkFilesExist && options.loadModels) checkModels(scene);
        for (const auto& warning : scene.warnings) log::warning(fileName, ": ", warning);
        return scene;
    } catch (const JsonSyntaxError& error) {
        return Error{describeJsonError(fileName, error)};
    } catch (const SceneFieldError& error) {
        return Error{describeJsonError(fileName, error)};
    } catch (const std::exception& error) {
        // Nothing above should get here; if it does, the caller still gets a message instead of a crash.
        return Error{cat(fileName, ": cannot read the scene: ", error.what())};
    }
}

Result<Scene> loadScene(const fs::path& file, const SceneLoadOptions& options) {
    auto text = readFile(file, file_limits::scene);
    if (!text) return Error{text.error()};
    return parseScene(*text, file, options);
}

}  // namespace fx
