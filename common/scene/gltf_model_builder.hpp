#pragma once
// Builds a GltfModel from what tinygltf parsed. Internal to the glTF loader; its methods live in
// files by what they read: gltf_model_builder.cpp (textures, materials, nodes),
// gltf_mesh_reader.cpp (meshes), gltf_animation_reader.cpp (skins and animations).
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "base/log.hpp"
#include "base/result.hpp"
#include "scene/gltf_model.hpp"

namespace fx::gltf_detail {

namespace fs = std::filesystem;

constexpr int kTriangles = 4, kTriangleStrip = 5, kTriangleFan = 6;

// Encoded image bytes, captured instead of decoded: the GL layer decodes what it uploads.
struct CapturedImages {
    std::map<int, std::vector<unsigned char>> bytes;
};

// Collects what goes into one model, with the file name on every message.
class ModelBuilder {
public:
    ModelBuilder(const tinygltf::Model& m, const fs::path& file, const fs::path& baseDir,
                 CapturedImages& images)
        : m_(m), baseDir_(baseDir), images_(images) {
        model_.file = file;
    }

    Result<GltfModel> build();

private:
    const tinygltf::Model& m_;
    fs::path baseDir_;
    CapturedImages& images_;
    GltfModel model_;

    void warn(std::string message) { model_.warnings.push_back(std::move(message)); }

    static std::string named(const char* kind, std::size_t index, const std::string& name) {
        return name.empty() ? cat(kind, " ", index) : cat(kind, " '", name, "'");
    }

    // gltf_model_builder.cpp
    void readTextures();
    int textureIndex(int index, const std::string& what);
    void readMaterials();
    Status readNodes();

    // gltf_mesh_reader.cpp
    Status readIndices(const tinygltf::Primitive& p, std::size_t vertices, const std::string& what,
                       std::vector<std::uint32_t>& out);
    Status readMesh(std::size_t meshIndex);

    // gltf_animation_reader.cpp
    Status readSkin(std::size_t index);
    void checkSkinnedNodes();
    Status readAnimation(std::size_t index);
};

}  // namespace fx::gltf_detail
