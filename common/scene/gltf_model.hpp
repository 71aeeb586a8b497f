#pragma once
// A glTF 2.0 model as fxlab uses it, without GL: triangle meshes (positions, normals, texture
// coordinates, joints and weights, 32-bit indices whatever the file stored), materials (base colour
// and emissive, each with an optional texture file), the node hierarchy, skins and animation clips.
// gltf_loader.hpp reads one from a file; effects/scene/gpu_model.hpp puts it on the GPU.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "geometry/mesh_data.hpp"
#include "scene/animation.hpp"
#include "scene/skin.hpp"

namespace fx {

// A texture a material refers to. Files are resolved against the glTF file's folder; images inside
// the file (a data: URI or a buffer view) keep their encoded bytes (PNG, JPEG) instead.
struct ModelTexture {
    std::filesystem::path file;
    std::vector<unsigned char> encoded;
    std::string mimeType;

    bool empty() const { return file.empty() && encoded.empty(); }
    bool operator==(const ModelTexture&) const = default;
};

struct ModelMaterial {
    std::string name;
    glm::vec4 baseColor{1.0f};  // linear RGBA factor
    int baseColorTexture = -1;  // index into GltfModel::textures, sRGB-encoded colour
    glm::vec3 emissive{0.0f};   // linear factor (times KHR_materials_emissive_strength when present)
    int emissiveTexture = -1;
    bool doubleSided = false;

    bool operator==(const ModelMaterial&) const = default;
};

// One glTF primitive: triangles with one material.
struct ModelPrimitive {
    // Normals are computed when the file has none; texture coordinates follow GL's convention
    // (v = 0 at the bottom row of the image), so the loader stores 1 - v of the file's value.
    MeshData mesh;
    std::vector<JointInfluence> influences;  // one per vertex when skinned, else empty
    int material = -1;                       // -1: the default material (white)
    bool generatedNormals = false;

    bool skinned() const { return !influences.empty(); }
};

struct ModelMesh {
    std::string name;
    std::vector<ModelPrimitive> primitives;
};

struct GltfModel {
    std::filesystem::path file;
    std::vector<ModelMesh> meshes;
    std::vector<ModelMaterial> materials;
    std::vector<ModelTexture> textures;
    std::vector<ModelNode> nodes;
    std::vector<int> roots;  // the default scene's root nodes
    std::vector<Skin> skins;
    std::vector<AnimationClip> clips;
    std::vector<std::string> warnings;  // what was odd but loadable (unsupported features skipped)

    const AnimationClip* findClip(const std::string& name) const;
    std::size_t vertexCount() const;
    std::size_t triangleCount() const;
    bool skinned() const { return !skins.empty(); }
    // Nodes that hold a mesh, in node order.
    std::vector<int> meshNodes() const;
};

}  // namespace fx
