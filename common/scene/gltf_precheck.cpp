#include "scene/gltf_precheck.hpp"

#include <cstdint>
#include <cstring>

#include <nlohmann/json.hpp>

#include "base/log.hpp"
#include "base/message_text.hpp"

namespace fx {
namespace {

using Json = nlohmann::json;

std::uint32_t littleEndianWord(std::span<const std::byte> bytes, std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v |= std::uint32_t(bytes[at + i]) << (8 * i);
    return v;
}

// "skin 0 'rig'", "mesh 2": the index always (what a validator names), the name where there is one.
std::string describe(std::string_view kind, std::size_t index, const Json& object) {
    auto name = object.find("name");
    if (name == object.end() || !name->is_string() || name->get_ref<const std::string&>().empty())
        return cat(kind, " ", index);
    return cat(kind, " ", index, " '", excerpt(name->get_ref<const std::string&>()), "'");
}

// The array `key` of `object`, or nothing.
const Json* arrayAt(const Json& object, const char* key) {
    auto it = object.find(key);
    return it != object.end() && it->is_array() ? &*it : nullptr;
}

std::optional<std::string> skinWithoutJoints(const Json& root) {
    const Json* skins = arrayAt(root, "skins");
    if (!skins) return std::nullopt;
    for (std::size_t i = 0; i < skins->size(); ++i) {
        const Json& skin = (*skins)[i];
        if (!skin.is_object() || arrayAt(skin, "joints")) continue;
        return cat(describe("skin", i, skin),
                   ": has no \"joints\"; glTF 2.0 requires skin.joints, the nodes its vertices follow");
    }
    return std::nullopt;
}

// An accessor a Draco primitive names that has no data outside the compressed stream.
std::optional<std::int64_t> accessorWithoutData(const Json& root, const Json& primitive) {
    const Json* accessors = arrayAt(root, "accessors");
    auto lacksData = [&](const Json& index) {
        if (!accessors || !index.is_number_integer()) return false;
        const auto i = index.get<std::int64_t>();
        if (i < 0 || std::size_t(i) >= accessors->size()) return false;
        const Json& accessor = (*accessors)[std::size_t(i)];
        return accessor.is_object() && !accessor.contains("bufferView");
    };
    if (auto indices = primitive.find("indices"); indices != primitive.end() && lacksData(*indices))
        return indices->get<std::int64_t>();
    if (auto attributes = primitive.find("attributes");
        attributes != primitive.end() && attributes->is_object())
        for (const Json& index : *attributes)
            if (lacksData(index)) return index.get<std::int64_t>();
    return std::nullopt;
}

std::optional<std::string> dracoWithoutCopy(const Json& root) {
    const Json* meshes = arrayAt(root, "meshes");
    if (!meshes) return std::nullopt;
    for (std::size_t m = 0; m < meshes->size(); ++m) {
        const Json& mesh = (*meshes)[m];
        const Json* primitives = mesh.is_object() ? arrayAt(mesh, "primitives") : nullptr;
        if (!primitives) continue;
        for (std::size_t p = 0; p < primitives->size(); ++p) {
            const Json& primitive = (*primitives)[p];
            if (!primitive.is_object()) continue;
            auto extensions = primitive.find("extensions");
            if (extensions == primitive.end() || !extensions->is_object() ||
                !extensions->contains("KHR_draco_mesh_compression"))
                continue;
            if (auto accessor = accessorWithoutData(root, primitive))
                return cat(
                    describe("mesh", m, mesh), " primitive ", p,
                    ": compressed with Draco (KHR_draco_mesh_compression), which fxlab does not decode, and accessor ",
                    *accessor, " has no uncompressed copy (no bufferView)");
        }
    }
    return std::nullopt;
}

}  // namespace

bool isGlb(std::span<const std::byte> bytes) {
    return bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
}

std::optional<std::string_view> glbJsonChunk(std::span<const std::byte> bytes) {
    // Header: magic, version, length; then the first chunk: length, type "JSON", data.
    if (!isGlb(bytes) || bytes.size() < 20) return std::nullopt;
    const std::uint32_t length = littleEndianWord(bytes, 12);
    if (std::memcmp(bytes.data() + 16, "JSON", 4) != 0 || length > bytes.size() - 20) return std::nullopt;
    return std::string_view(reinterpret_cast<const char*>(bytes.data() + 20), length);
}

std::optional<std::string> findUnnamedGltfRefusal(std::string_view document) {
    Json root = Json::parse(document, nullptr, /*allow_exceptions=*/false);
    if (!root.is_object()) return std::nullopt;
    if (auto refusal = skinWithoutJoints(root)) return refusal;
    return dracoWithoutCopy(root);
}

}  // namespace fx
