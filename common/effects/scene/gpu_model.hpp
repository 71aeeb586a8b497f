#pragma once
// One glTF object of a scene on the GPU: a mesh per node that holds one (static, or skinned with its
// own joint buffer and posed vertices), the materials with their textures, and the pose of the node
// hierarchy at the time last animated. The CPU model (GltfModel) is shared between objects that use
// the same file; the GPU buffers belong to this object, so two instances can play different times.
#include <memory>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "effects/scene/gpu_mesh.hpp"
#include "effects/scene/gpu_skinning.hpp"
#include "effects/scene/joint_buffer.hpp"
#include "effects/scene/material_textures.hpp"
#include "effects/scene/skinned_mesh.hpp"
#include "scene/gltf_model.hpp"

namespace fx {

// How skinned meshes are drawn.
enum class SkinnedDraw {
    posed,   // the vertices GpuSkinning wrote: works with every program (static or not)
    source,  // the bind pose with joints and weights and the joint SSBO bound: for a skinning shader
};

// What a draw call sets besides the model matrix.
struct ModelDrawStyle {
    glm::vec3 tint{1.0f};           // multiplies each material's base colour
    glm::vec3 addedEmissive{0.0f};  // added to each material's emissive colour
    bool setMaterial = true;        // upload base colour and emissive (a depth-only program has neither)
    bool bindTextures = true;       // base colour texture on unit 0, emissive on unit 1
    GLuint baseColorTexture = 0;    // not 0: bound instead of every material's own base colour texture
    SkinnedDraw skinned = SkinnedDraw::posed;
};

class GpuModel {
public:
    GpuModel(std::shared_ptr<const GltfModel> model, MaterialTextures& textures, std::string_view label);

    // Poses the hierarchy at `clipSeconds` of `clip` (nullptr: the rest pose), uploads the joint
    // matrices and skins every skinned mesh on the GPU (when `skinning` is usable).
    void animate(const AnimationClip* clip, float clipSeconds, const GpuSkinning* skinning);

    // Draws every mesh with `objectModel` times its node's world matrix.
    void draw(GLuint program, const glm::mat4& objectModel, const ModelDrawStyle& style) const;

    const GltfModel& model() const { return *model_; }
    const std::vector<glm::mat4>& nodeWorld() const { return world_; }
    // Joint matrices last uploaded for the mesh on `node` (empty if the node has no skinned mesh).
    const std::vector<glm::mat4>& jointMatrices(int node) const;
    std::size_t skinnedMeshes() const;
    std::size_t unweightedVertices() const;
    // The posed mesh of a node's primitive, for tests that read the vertices back.
    const SkinnedMesh* skinnedMesh(int node, std::size_t primitive) const;

private:
    struct Part {
        GpuMesh staticMesh;
        SkinnedMesh skinnedMesh;
        bool skinned = false;
        int material = -1;
    };
    struct Instance {
        int node = -1;
        std::vector<Part> parts;
        JointMatrixBuffer joints;
        std::vector<glm::mat4> jointMatrices;
        bool skinned = false;
    };
    struct MaterialGpu {
        glm::vec3 baseColor{1.0f};
        glm::vec3 emissive{0.0f};
        GLuint baseColorTexture = 0;
        GLuint emissiveTexture = 0;
    };

    std::shared_ptr<const GltfModel> model_;
    std::vector<Instance> instances_;
    std::vector<MaterialGpu> materials_;
    MaterialGpu defaultMaterial_;
    std::vector<glm::mat4> world_;
};

}  // namespace fx
