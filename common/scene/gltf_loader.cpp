#include "scene/gltf_loader.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>

#include <tiny_gltf.h>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "base/file_io.hpp"
#include "base/log.hpp"
#include "base/path_rule.hpp"
#include "scene/gltf_files.hpp"
#include "scene/gltf_model_builder.hpp"
#include "scene/gltf_precheck.hpp"
#include "scene/scene_loader.hpp"

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

// tinygltf opens no file itself: it is given the bytes readGltfFiles read under the path rule
// (scene/gltf_files.hpp). Its own FileExists would fopen the path, which waits forever on a FIFO.
bool knownFile(const std::string& path, void* user) {
    const auto* files = static_cast<const GltfFiles*>(user);
    const std::string key = gltfFileKey(path);
    return files->bytes.contains(key) || files->unreadImages.contains(key);
}

bool readKnownFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    const auto* files = static_cast<const GltfFiles*>(user);
    auto it = files->bytes.find(gltfFileKey(path));
    if (it == files->bytes.end()) {
        if (err) *err += "not read";  // an unread image: fxlab has warned in its own words
        return false;
    }
    *out = it->second;
    return true;
}

std::string unexpanded(const std::string& path, void*) {
    return path;  // no shell expansion of a file's words
}

void useFxlabFiles(tinygltf::TinyGLTF& loader, GltfFiles& files) {
    tinygltf::FsCallbacks callbacks{};
    callbacks.FileExists = &knownFile;
    callbacks.ExpandFilePath = &unexpanded;
    callbacks.ReadWholeFile = &readKnownFile;
    callbacks.WriteWholeFile = &tinygltf::WriteWholeFile;  // never called: fxlab writes no glTF through it
    callbacks.user_data = &files;
    loader.SetFsCallbacks(callbacks);
}

// tinygltf's lines about an image fxlab did not read (it has said why in its own words).
bool aboutAnUnreadImage(const std::string& line) {
    return line.starts_with("File read error : ") ||
           line.starts_with("Failed to load external 'uri' for image[") ||
           line.starts_with("File not found : ");
}

// The folder a model's files must stay in: the asset root (the default one when none is given) when it
// holds the model's folder, else the model's own folder.
fs::path rootFor(const fs::path& modelFolder, const fs::path& assetRoot) {
    const fs::path root = resolvedPath(fs::absolute(assetRoot.empty() ? defaultAssetRoot() : assetRoot));
    const fs::path folder = resolvedPath(fs::absolute(modelFolder));
    return isInsideFolder(folder, root) ? root : folder;
}

// Extensions fxlab reads; any other one a file *requires* changes what the file means (compressed
// geometry, for one), so such a file is refused rather than drawn wrong.
constexpr std::string_view kSupportedExtensions[] = {"KHR_materials_emissive_strength"};

bool supported(const std::string& extension) {
    for (std::string_view known : kSupportedExtensions)
        if (extension == known) return true;
    return false;
}

std::string trimmed(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    return text;
}

Result<GltfModel> finish(bool ok, const tinygltf::Model& m, const std::string& err, const std::string& warn,
                         const fs::path& file, const fs::path& baseDir, CapturedImages& images,
                         const GltfFiles& files) {
    if (!ok) {
        // tinygltf sometimes puts its only reason among the warnings.
        std::string message = trimmed(err.empty() ? warn : err);
        if (message.empty()) message = "tinygltf refused it without giving a reason";
        return Error{cat(file.string(), ": ", message)};
    }
    for (const std::string& extension : m.extensionsRequired)
        if (!supported(extension))
            return Error{cat(file.string(), ": requires the extension ", extension,
                             ", which fxlab does not implement")};
    auto model = ModelBuilder(m, file, baseDir, images).build();
    if (!model) return Error{cat(file.string(), ": ", model.error())};
    // tinygltf's own warnings, one per line.
    std::size_t start = 0;
    while (start < warn.size()) {
        std::size_t end = warn.find('\n', start);
        if (end == std::string::npos) end = warn.size();
        const std::string line = warn.substr(start, end - start);
        if (end > start && !(files.warnings.size() > 0 && aboutAnUnreadImage(line)))
            model->warnings.push_back(line);
        start = end + 1;
    }
    model->warnings.insert(model->warnings.begin(), files.warnings.begin(), files.warnings.end());
    for (const std::string& extension : m.extensionsUsed)
        if (!supported(extension)) model->warnings.push_back(cat("extension ", extension, " is ignored"));
    // Not logged here: the scene loader says them once (the meshes load the same file again for the GPU).
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

Result<GltfModel> parseGltfBytes(std::span<const std::byte> bytes, const fs::path& baseDir,
                                 const fs::path& nominalFile, const fs::path& root) {
    const bool binary = isGlb(bytes);
    // What tinygltf would refuse without naming the rule, refused here with it.
    std::optional<std::string_view> document =
        binary ? glbJsonChunk(bytes)
               : std::optional<std::string_view>(
                     std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    if (document)
        if (auto refusal = findUnnamedGltfRefusal(*document))
            return Error{cat(nominalFile.string(), ": ", *refusal)};
    auto files = document ? readGltfFiles(*document, baseDir, root.empty() ? rootFor(baseDir, {}) : root)
                          : Result<GltfFiles>(GltfFiles{});
    if (!files) return Error{cat(nominalFile.string(), ": ", files.error())};
    tinygltf::TinyGLTF loader;
    useFxlabFiles(loader, *files);
    CapturedImages images;
    loader.SetImageLoader(&captureImage, &images);
    tinygltf::Model m;
    std::string err, warn;
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    const auto size = static_cast<unsigned int>(bytes.size());
    bool ok = binary ? loader.LoadBinaryFromMemory(&m, &err, &warn, data, size, baseDir.string())
                     : loader.LoadASCIIFromString(&m, &err, &warn, reinterpret_cast<const char*>(data), size,
                                                  baseDir.string());
    return finish(ok, m, err, warn, nominalFile, baseDir, images, *files);
}

Result<GltfModel> loadGltf(const fs::path& file, const fs::path& assetRoot) {
    std::error_code ec;
    if (!fs::exists(file, ec)) return Error{cat(file.string(), ": no such file")};
    auto bytes = readFile(file, file_limits::gltf);
    if (!bytes) return Error{bytes.error()};
    return parseGltfBytes(std::as_bytes(std::span(bytes->data(), bytes->size())), file.parent_path(), file,
                          rootFor(file.parent_path(), assetRoot));
}

Result<GltfModel> parseGltf(const std::string& json, const fs::path& baseDir, const fs::path& nominalFile) {
    return parseGltfBytes(std::as_bytes(std::span(json.data(), json.size())), baseDir, nominalFile);
}

}  // namespace fx
