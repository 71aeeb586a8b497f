#pragma once
// The scene a frame draws, as one value: the scene file's data, its meshes on the GPU and the scene
// time. The runner makes the meshes once (and poses the skinned ones every frame the scene calls for
// animation), puts the three in FrameInfo::world, and a lesson hands them to the effects that draw the
// scene:
//
//   HdrSceneTargets hdr = scenePass_->declare(graph, frame.world);
//
// A World is three words: pass bodies copy it. The scene and the meshes it points at live as long as
// the run.
#include "effects/scene/scene_meshes.hpp"
#include "scene/scene.hpp"

namespace fx {

class World {
public:
    World() = default;  // nothing to draw (a frame whose passes draw no scene)
    World(const Scene& scene, const SceneMeshes& meshes, double seconds)
        : scene_(&scene), meshes_(&meshes), seconds_(seconds) {}

    const Scene& scene() const { return *scene_; }
    const SceneMeshes& meshes() const { return *meshes_; }
    double seconds() const { return seconds_; }

    // The same meshes at the same time, seen through another copy of the scene (a lesson that moves
    // the camera or the lens keeps a scene of its own).
    World seenThrough(const Scene& scene) const { return {scene, *meshes_, seconds_}; }

    // Draws the objects with `program` (SceneMeshes::draw at this time); how many it drew.
    std::size_t draw(GLuint program, const MeshDrawOptions& options = {}) const {
        return meshes_->draw(program, *scene_, seconds_, options);
    }

private:
    const Scene* scene_ = nullptr;
    const SceneMeshes* meshes_ = nullptr;
    double seconds_ = 0;
};

}  // namespace fx
