#include "scene/gltf_loader.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>

#include <tiny_gltf.h>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "base/log.hpp"
#include "scene/gltf_model_builder.hpp"

namespace fx {
namespace {

namespace fs = std::filesystem;
using namespace gltf_detail;

bool captureImage(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                  const unsigned char* bytes, int size, void* user) {
    auto* captured = static_cast<CapturedImages*>(user);
    if (bytes && size > 0) captured->bytes[index].assign(bytes, bytes + size);
    image->width = image->height = image->component = -1;  // not decoded
    return true;
}

Result<GltfModel> finish(bool ok, const tinygltf::Model& m, const std::string& err, const std::string& warn,
                         const fs::path& file, const fs::path& baseDir, CapturedImages& images) {
    if (!ok) {
        std::string message = err.empty() ? "tinygltf could not read it" : err;
        while (!message.empty() && message.back() == '\n') message.pop_back();
        return Error{cat(file.string(), ": ", message)};
    }
    auto model = ModelBuilder(m, file, baseDir, images).build();
    if (!model) return Error{cat(file.string(), ": ", model.error())};
    // tinygltf's own warnings, one per line.
    std::size_t start = 0;
    while (start < warn.size()) {
        std::size_t end = warn.find('\n', start);
        if (end == std::string::npos) end = warn.size();
        if (end > start) model->warnings.push_back(warn.substr(start, end - start));
        start = end + 1;
    }
    for (const auto& w : model->warnings) log::warning(file.filename().string(), ": ", w);
    return model;
}

}  // namespace

const AnimationClip* GltfModel::findClip(const std::string& name) const {
    for (const auto& clip : clips)
        if (clip.name == name) return &clip;
    return nullptr;
}

std::size_t GltfModel::vertexCount() const {
    std::size_t n = 0;
    for (const auto& mesh : meshes)
        for (const auto& p : mesh.primitives) n += p.mesh.vertexCount();
    return n;
}

std::size_t GltfModel::triangleCount() const {
    std::size_t n = 0;
    for (const auto& mesh : meshes)
        for (const auto& p : mesh.primitives) n += p.mesh.triangleCount();
    return n;
}

std::vector<int> GltfModel::meshNodes() const {
    std::vector<int> result;
    for (std::size_t i = 0; i < nodes.size(); ++i)
        if (nodes[i].mesh >= 0) result.push_back(static_cast<int>(i));
    return result;
}

void computeNormals(MeshData& mesh) {
    std::vector<glm::vec3> sum(mesh.positions.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        if (a >= sum.size() || b >= sum.size() || c >= sum.size()) continue;
        // The cross product's length is twice the area, so big triangles weigh more.
        glm::vec3 n =
            glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
        sum[a] += n;
        sum[b] += n;
        sum[c] += n;
    }
    mesh.normals.resize(mesh.positions.size());
    for (std::size_t i = 0; i < sum.size(); ++i) {
        float length = glm::length(sum[i]);
        mesh.normals[i] = length > 1e-20f ? sum[i] / length : glm::vec3(0.0f, 1.0f, 0.0f);
    }
}

Result<GltfModel> loadGltf(const fs::path& file) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) return Error{cat(file.string(), ": no such file")};
    tinygltf::TinyGLTF loader;
    CapturedImages images;
    loader.SetImageLoader(&captureImage, &images);
    tinygltf::Model m;
    std::string err, warn;
    bool binary = file.extension() == ".glb" || file.extension() == ".GLB";
    bool ok = binary ? loader.LoadBinaryFromFile(&m, &err, &warn, file.string())
                     : loader.LoadASCIIFromFile(&m, &err, &warn, file.string());
    return finish(ok, m, err, warn, file, file.parent_path(), images);
}

Result<GltfModel> parseGltf(const std::string& json, const fs::path& baseDir, const fs::path& nominalFile) {
    tinygltf::TinyGLTF loader;
    CapturedImages images;
    loader.SetImageLoader(&captureImage, &images);
    tinygltf::Model m;
    std::string err, warn;
    bool ok = loader.LoadASCIIFromString(&m, &err, &warn, json.c_str(),
                                         static_cast<unsigned int>(json.size()), baseDir.string());
    return finish(ok, m, err, warn, nominalFile, baseDir, images);
}

}  // namespace fx
