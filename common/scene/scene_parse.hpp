#pragma once
// The scene loader's section readers, one per part of the file. Internal to common/scene: they throw
// SceneFieldError, which parseScene turns into an Error.
#include <filesystem>
#include <string_view>
#include <utility>

#include "scene/json_field_reader.hpp"
#include "scene/scene.hpp"

namespace fx {

// Reads asset paths: resolves them against the scene's folder, keeps them inside the asset root and,
// when asked, checks that the file exists.
class AssetPathReader {
public:
    AssetPathReader(std::filesystem::path sceneFolder, std::filesystem::path assetRoot, bool checkExists)
        : sceneFolder_(std::move(sceneFolder)), assetRoot_(std::move(assetRoot)), checkExists_(checkExists) {}

    AssetRef optional(JsonFieldReader& object, std::string_view key) const;
    AssetRef required(JsonFieldReader& object, std::string_view key) const;

private:
    std::filesystem::path sceneFolder_;
    std::filesystem::path assetRoot_;
    bool checkExists_;
};

Camera parseCamera(JsonFieldReader& camera);
Light parseLight(JsonFieldReader& light);
LightGrid parseLightGrid(JsonFieldReader& grid);
SceneObject parseObject(JsonFieldReader& object, const AssetPathReader& assets);
ParticleEmitter parseEmitter(JsonFieldReader& emitter, const AssetPathReader& assets);
CloudLayer parseCloudLayer(JsonFieldReader& cloud, const AssetPathReader& assets);
PostEffects parsePostEffects(JsonFieldReader& post, const Camera& camera);

// A setting that starts a lesson's parameter (scene/scene_settings.cpp), read at `key` with the range
// it declares: `fallback` when the file leaves it out, a refusal when it is required. Where its range
// has no end (a focus distance), the file may write "infinity".
float readSetting(JsonFieldReader& reader, std::string_view key, std::string_view path, float fallback);
int readIntegerSetting(JsonFieldReader& reader, std::string_view key, std::string_view path, int fallback);
// A setting's range as the reader checks it (an infinite end becomes the largest float).
NumberRange settingRange(std::string_view path);

// Ranges shared by several sections.
inline constexpr NumberRange kCoordinateRange{-1.0e5, 1.0e5};  // metres
inline constexpr NumberRange kHdrColorRange{0.0, 1.0e4};       // linear colour, may exceed 1
inline constexpr NumberRange kUnitRange{0.0, 1.0};
inline constexpr NumberRange kLengthRange{0.0, 1.0e4, true, false};  // (0, 10 km]

}  // namespace fx
