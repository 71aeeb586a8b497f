#pragma once
// The GPU side of a scene's objects: a mesh per built-in primitive, a GpuModel per glTF object, and a
// draw call per mesh with its model matrix and material in the uniforms every lit shader declares
// (shaders/common/scene_uniforms.glsl). Material textures are bound on units 0 (base colour) and 1
// (emissive); untextured materials get plain white, so a shader may always multiply by them.
//
// Skinned glTF objects are posed on the GPU (GpuSkinning, transform feedback) at the time of the
// frame, then drawn like static meshes: any program draws them in the current pose, including one
// without skinning in it (lesson 01's lit program). A lesson that skins in its own vertex shader draws
// with MeshDrawOptions::skinned = SkinnedDraw::source instead (shaders/effects/skinning/
// skinned_scene.vert is such a shader).
//
//   SceneMeshes meshes(scene);
//   meshes.update(frame.seconds);                      // animation + GPU skinning, once per frame
//   SceneMeshes::setFrameUniforms(program, scene, camera);
//   meshes.draw(program, scene, frame.seconds);        // poses first if update() was not called
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "effects/scene/camera_matrices.hpp"
#include "effects/scene/gpu_mesh.hpp"
#include "effects/scene/gpu_model.hpp"
#include "effects/scene/gpu_skinning.hpp"
#include "effects/scene/material_textures.hpp"
#include "effects/scene/scene_bindings.hpp"
#include "scene/scene.hpp"

namespace fx {

// Which objects a draw covers, by whether they have a skinned mesh. A shadow pass draws the two
// groups with two programs (Shader effects chapter §2: static meshes first, then skinned, one switch).
enum class SkinFilter {
    all,
    withoutSkin,  // primitives and glTF objects with no skinned mesh
    skinnedOnly,  // glTF objects with at least one skinned mesh
};

// Which objects a draw covers and what it sets. The defaults draw everything with its material.
struct MeshDrawOptions {
    bool primitives = true;          // built-in shapes
    bool models = true;              // glTF objects
    bool shadowCastersOnly = false;  // skip objects with castsShadows = false
    bool setMaterial = true;         // upload base colour and emissive (a depth-only program has neither)
    bool bindTextures = true;
    SkinnedDraw skinned = SkinnedDraw::posed;
    SkinFilter skinFilter = SkinFilter::all;
    // A world transform applied after each object's own: draws a copy of the scene's objects
    // elsewhere (lesson 02's crowd is the character drawn at many placements).
    glm::mat4 placement{1.0f};
    // When set, only the objects it accepts are drawn (lesson 01 draws one object with another program).
    std::function<bool(const SceneObject&)> only;
};

class SceneMeshes {
public:
    explicit SceneMeshes(const Scene& scene);
    ~SceneMeshes();
    SceneMeshes(SceneMeshes&&) noexcept;
    SceneMeshes& operator=(SceneMeshes&&) noexcept;

    // Model matrix of an object at a time (its transform plus its simple motion).
    static glm::mat4 modelAt(const SceneObject& object, double seconds);

    // Sets the camera and the first directional light (or a default one) on `program`.
    static void setFrameUniforms(GLuint program, const Scene& scene, const CameraMatrices& camera);

    // Poses every animated glTF object at `seconds` of scene time (each clip loops; the time is wrapped
    // by the clip's length before it reaches a float) and skins the skinned ones on the GPU.
    void update(double seconds);
    // Draws the objects with their materials. Poses first if the last update() was for another time.
    void draw(GLuint program, const Scene& scene, double seconds) const;
    // Returns how many objects it drew.
    std::size_t draw(GLuint program, const Scene& scene, double seconds,
                     const MeshDrawOptions& options) const;

    std::size_t drawnObjects() const;
    // One entry per scene object, drawable or not (the indices model() and isSkinned() take).
    std::size_t objectCount() const { return objects_.size(); }
    // Objects that cannot be drawn, with the reason ("robot (models/robot.gltf: no such file)").
    const std::vector<std::string>& notDrawn() const { return notDrawn_; }
    // glTF objects with a skinned mesh, and how many GPU skinning updates have run.
    std::size_t skinnedObjects() const;
    // Whether object `index` has a skinned mesh (what SkinFilter sorts by).
    bool isSkinned(std::size_t index) const;
    std::uint64_t skinningUpdates() const { return skinningUpdates_; }
    // The GPU model of object `index` (nullptr for primitives and models that failed to load).
    const GpuModel* model(std::size_t index) const;
    // The clip time object `index` was last posed at.
    float clipTime(std::size_t index) const;
    const MaterialTextures& textures() const { return *textures_; }

private:
    struct ObjectMeshes {
        GpuMesh primitive;
        GLuint baseColorTexture = 0;
        std::unique_ptr<GpuModel> model;
        std::shared_ptr<const AnimationClip> clip;  // the object's clips, merged (clip_selection.hpp)
        float speed = 1.0f;
    };
    std::vector<ObjectMeshes> objects_;
    std::vector<std::string> notDrawn_;
    std::map<std::string, std::shared_ptr<const GltfModel>> files_;
    std::unique_ptr<MaterialTextures> textures_;
    std::unique_ptr<GpuSkinning> skinning_;  // only when the scene has something to skin
    // draw() is const but poses on demand: the pose is a cache of the time it was computed for.
    mutable std::vector<float> clipTimes_;  // per object
    mutable double posedAt_ = 0.0;
    mutable bool posed_ = false;
    mutable std::uint64_t skinningUpdates_ = 0;

    void pose(double seconds) const;
};

}  // namespace fx
