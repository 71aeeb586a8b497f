#pragma once
// A scene as described by a scene file (res/scenes/*.json, format in docs/scene-format.md). Plain data
// with defaults: loading fills it, saving writes it back, and what it contains decides which simulations
// and passes a lesson runs (see scene_features.hpp).
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/scene_camera.hpp"
#include "scene/scene_cloud.hpp"
#include "scene/scene_emitter.hpp"
#include "scene/scene_light.hpp"
#include "scene/scene_light_grid.hpp"
#include "scene/scene_object.hpp"
#include "scene/scene_post.hpp"

namespace fx {

// The "version" a scene file may state; files without one are read as this version.
inline constexpr int kSceneFormatVersion = 1;

struct Scene {
    std::string name;
    std::string description;
    glm::vec3 background{0.02f, 0.02f, 0.03f};  // linear HDR sky colour behind everything
    glm::vec3 ambient{0.03f};                   // linear HDR light that reaches every surface
    Camera camera;
    std::vector<Light> lights;
    std::vector<LightGrid> lightGrids;  // generated point lights (scene_light_grid.hpp)
    std::vector<SceneObject> objects;
    std::vector<ParticleEmitter> emitters;
    std::vector<CloudLayer> clouds;
    PostEffects postEffects;

    std::filesystem::path file;         // where it was loaded from (absolute); paths resolve against it
    std::vector<std::string> warnings;  // "json.path: what is odd", from loading

    bool operator==(const Scene&) const = default;
};

// The scene's lights followed by every grid's lights, expanded.
std::vector<Light> allLights(const Scene& scene);

// Every file the scene refers to (glTF models and textures), resolved, sorted, without repeats.
std::vector<std::filesystem::path> referencedFiles(const Scene& scene);

}  // namespace fx
