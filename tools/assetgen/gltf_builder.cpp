#include "gltf_builder.hpp"
#include "base/json_text.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace fx::assetgen {
namespace {

constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr int kUnsignedByte = 5121, kUnsignedShort = 5123, kUnsignedInt = 5125, kFloat = 5126;
constexpr double kGrid = 1048576.0;  // 2^20

template <class T>
std::vector<float> flatten(const std::vector<T>& values, int components) {
    std::vector<float> out;
    out.reserve(values.size() * static_cast<std::size_t>(components));
    for (const T& v : values)
        for (int c = 0; c < components; ++c) out.push_back(snap(v[c]));
    return out;
}

}  // namespace

float snap(float v) {
    return static_cast<float>(std::nearbyint(static_cast<double>(v) * kGrid) / kGrid);
}
glm::vec3 snap(glm::vec3 v) {
    return {snap(v.x), snap(v.y), snap(v.z)};
}

double decimal(float v) {
    char text[64];
    auto [end, error] = std::to_chars(text, text + sizeof(text) - 1, v);
    if (error != std::errc()) return static_cast<double>(v);
    *end = '\0';
    return std::strtod(text, nullptr);
}

Json decimals(glm::vec3 v) {
    return Json::array({decimal(v.x), decimal(v.y), decimal(v.z)});
}

GltfBuilder::GltfBuilder(std::string binUri) {
    doc_["asset"] = {{"version", "2.0"}, {"generator", "fxlab tools/assetgen"}};
    doc_["scene"] = 0;
    doc_["scenes"] = Json::array({Json{{"nodes", Json::array()}}});
    doc_["buffers"] = Json::array({Json{{"uri", std::move(binUri)}, {"byteLength", 0}}});
}

int GltfBuilder::append(const char* array, Json value) {
    if (!doc_.contains(array)) doc_[array] = Json::array();
    doc_[array].push_back(std::move(value));
    return static_cast<int>(doc_[array].size()) - 1;
}

int GltfBuilder::addView(const void* data, std::size_t bytes, int target) {
    while (bin_.size() % 4 != 0) bin_.push_back(std::byte{0});
    std::size_t offset = bin_.size();
    bin_.resize(offset + bytes);
    if (bytes > 0) std::memcpy(bin_.data() + offset, data, bytes);
    Json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}};
    if (target != 0) view["target"] = target;
    return append("bufferViews", std::move(view));
}

int GltfBuilder::addAccessor(int view, int componentType, std::size_t count, const char* type, Json extra) {
    Json accessor = {
        {"bufferView", view}, {"componentType", componentType}, {"count", count}, {"type", type}};
    for (auto& [key, value] : extra.items()) accessor[key] = value;
    return append("accessors", std::move(accessor));
}

int GltfBuilder::addPositions(const std::vector<glm::vec3>& values) {
    std::vector<float> flat = flatten(values, 3);
    Json lo = Json::array(), hi = Json::array();
    for (int c = 0; c < 3; ++c) {
        float mn = 0.0f, mx = 0.0f;
        for (std::size_t i = 0; i < values.size(); ++i) {
            float v = flat[i * 3 + static_cast<std::size_t>(c)];
            mn = i == 0 ? v : std::min(mn, v);
            mx = i == 0 ? v : std::max(mx, v);
        }
        lo.push_back(mn);
        hi.push_back(mx);
    }
    int view = addView(flat.data(), flat.size() * sizeof(float), kArrayBuffer);
    return addAccessor(view, kFloat, values.size(), "VEC3", {{"min", lo}, {"max", hi}});
}

int GltfBuilder::addVec3(const std::vector<glm::vec3>& values) {
    std::vector<float> flat = flatten(values, 3);
    return addAccessor(addView(flat.data(), flat.size() * sizeof(float), kArrayBuffer), kFloat, values.size(),
                       "VEC3");
}

int GltfBuilder::addVec2(const std::vector<glm::vec2>& values) {
    std::vector<float> flat = flatten(values, 2);
    return addAccessor(addView(flat.data(), flat.size() * sizeof(float), kArrayBuffer), kFloat, values.size(),
                       "VEC2");
}

int GltfBuilder::addVec4(const std::vector<glm::vec4>& values) {
    std::vector<float> flat = flatten(values, 4);
    return addAccessor(addView(flat.data(), flat.size() * sizeof(float), kArrayBuffer), kFloat, values.size(),
                       "VEC4");
}

int GltfBuilder::addJoints8(const std::vector<std::array<std::uint8_t, 4>>& values) {
    int view = addView(values.data(), values.size() * 4, kArrayBuffer);
    return addAccessor(view, kUnsignedByte, values.size(), "VEC4");
}

int GltfBuilder::addWeights8(const std::vector<std::array<std::uint8_t, 4>>& values) {
    int view = addView(values.data(), values.size() * 4, kArrayBuffer);
    return addAccessor(view, kUnsignedByte, values.size(), "VEC4", {{"normalized", true}});
}

int GltfBuilder::addIndices16(const std::vector<std::uint32_t>& values) {
    std::vector<std::uint16_t> narrow(values.begin(), values.end());
    int view = addView(narrow.data(), narrow.size() * sizeof(std::uint16_t), kElementArrayBuffer);
    return addAccessor(view, kUnsignedShort, values.size(), "SCALAR");
}

int GltfBuilder::addIndices32(const std::vector<std::uint32_t>& values) {
    int view = addView(values.data(), values.size() * sizeof(std::uint32_t), kElementArrayBuffer);
    return addAccessor(view, kUnsignedInt, values.size(), "SCALAR");
}

int GltfBuilder::addTimes(const std::vector<float>& values) {
    std::vector<float> flat;
    for (float v : values) flat.push_back(snap(v));
    for (const auto& [known, accessor] : times_)
        if (known == flat) return accessor;
    int view = addView(flat.data(), flat.size() * sizeof(float), 0);
    int accessor = addAccessor(view, kFloat, flat.size(), "SCALAR",
                               {{"min", Json::array({flat.front()})}, {"max", Json::array({flat.back()})}});
    times_.emplace_back(flat, accessor);
    return accessor;
}

int GltfBuilder::addMat4(const std::vector<glm::mat4>& values) {
    std::vector<float> flat;
    for (const glm::mat4& m : values)
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) flat.push_back(snap(m[c][r]));  // column-major, as glTF stores it
    return addAccessor(addView(flat.data(), flat.size() * sizeof(float), 0), kFloat, values.size(), "MAT4");
}

int GltfBuilder::addImage(const std::string& uri) {
    return append("images", {{"uri", uri}});
}

int GltfBuilder::addTexture(int image) {
    if (sampler_ < 0) {
        // Linear filtering with mipmaps, repeating: 9729 LINEAR, 9987 LINEAR_MIPMAP_LINEAR, 10497 REPEAT.
        sampler_ = append("samplers",
                          {{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 10497}});
    }
    return append("textures", {{"sampler", sampler_}, {"source", image}});
}

int GltfBuilder::addMaterial(Json material) {
    return append("materials", std::move(material));
}
int GltfBuilder::addMesh(Json mesh) {
    return append("meshes", std::move(mesh));
}
int GltfBuilder::addNode(Json node) {
    return append("nodes", std::move(node));
}
int GltfBuilder::addSkin(Json skin) {
    return append("skins", std::move(skin));
}
int GltfBuilder::addAnimation(Json animation) {
    return append("animations", std::move(animation));
}

void GltfBuilder::setSceneRoots(const std::vector<int>& roots) {
    doc_["scenes"][0]["nodes"] = roots;
}

void GltfBuilder::useExtension(const std::string& name) {
    if (!doc_.contains("extensionsUsed")) doc_["extensionsUsed"] = Json::array();
    doc_["extensionsUsed"].push_back(name);
}

std::string GltfBuilder::gltfText() const {
    Json doc = doc_;
    doc["buffers"][0]["byteLength"] = bin_.size();
    return fx::dumpJson(doc, 1) + "\n";
}

}  // namespace fx::assetgen
