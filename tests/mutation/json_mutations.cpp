#include "json_mutations.hpp"

#include <cstdint>
#include <limits>

namespace mutation {
namespace {

using nlohmann::json;

// Every value's JSON pointer, in document order.
void collectPointers(const json& value, const json::json_pointer& at, std::vector<json::json_pointer>& out) {
    out.push_back(at);
    if (value.is_object()) {
        for (auto it = value.begin(); it != value.end(); ++it) collectPointers(*it, at / it.key(), out);
    } else if (value.is_array()) {
        for (std::size_t i = 0; i < value.size(); ++i) collectPointers(value[i], at / i, out);
    }
}

// Wrong types, extreme numbers (beyond a float, below its smallest step, the integer edges) and odd
// strings. JSON has no NaN or infinity: 1e400 (which overflows a double) stands for them in text.
std::vector<json> replacements() {
    return {
        json("text"),
        json(nullptr),
        json(true),
        json::array(),
        json::object(),
        json(0),
        json(-1),
        json(1e-300),
        json(1e39),
        json(-1e39),
        json(std::numeric_limits<std::uint64_t>::max()),
        json(std::numeric_limits<std::int64_t>::min()),
        json(0.5),
        json(std::string(5000, 'z')),
        json::array({1, 2, 3, 4, 5}),
    };
}

std::string withInfinity(const json& document, const json::json_pointer& at) {
    json copy = document;
    copy[at] = 123456789.0;
    std::string text = copy.dump();
    auto spot = text.find("123456789.0");
    if (spot != std::string::npos) text.replace(spot, 11, "1e400");
    return text;
}

}  // namespace

std::vector<Mutant> treeMutations(const json& document, int perValue) {
    std::vector<json::json_pointer> pointers;
    collectPointers(document, json::json_pointer(), pointers);
    const std::vector<json> values = replacements();
    std::vector<Mutant> out;
    for (std::size_t p = 1; p < pointers.size(); ++p) {  // 0 is the whole document
        const json::json_pointer& at = pointers[p];
        json removed = document;
        removed[at.parent_pointer()].erase(removed[at.parent_pointer()].is_object()
                                               ? removed[at.parent_pointer()].find(at.back())
                                               : removed[at.parent_pointer()].begin() +
                                                     static_cast<std::ptrdiff_t>(std::stoul(at.back())));
        out.push_back({"delete " + at.to_string(), removed.dump()});
        for (int k = 0; k < perValue; ++k) {
            std::size_t choice = (p * 7 + std::size_t(k) * 5) % (values.size() + 1);
            if (choice == values.size()) {
                out.push_back({"1e400 at " + at.to_string(), withInfinity(document, at)});
                continue;
            }
            json replaced = document;
            replaced[at] = values[choice];
            out.push_back({"replace " + at.to_string() + " with " + values[choice].dump().substr(0, 24),
                           replaced.dump()});
        }
    }
    return out;
}

std::vector<Mutant> textMutations(const std::string& text, int cuts, int inserts) {
    std::vector<Mutant> out;
    for (int i = 0; i < cuts; ++i) {
        std::size_t at = text.size() * std::size_t(i) / std::size_t(cuts);
        out.push_back({"truncate at " + std::to_string(at), text.substr(0, at)});
    }
    const std::string bytes[] = {std::string("\xff"), std::string("\xc3"), std::string("\xed\xa0\x80"),
                                 std::string(1, '\0'), std::string("\xef\xbb\xbf")};
    for (int i = 0; i < inserts; ++i) {
        std::size_t at = text.size() * std::size_t(2 * i + 1) / std::size_t(2 * inserts);
        const std::string& insert = bytes[std::size_t(i) % std::size(bytes)];
        out.push_back(
            {"insert byte(s) at " + std::to_string(at), text.substr(0, at) + insert + text.substr(at)});
    }
    out.push_back({"trailing NUL", text + std::string(1, '\0')});
    out.push_back({"empty", ""});
    return out;
}

std::vector<Mutant> gltfMutations(const json& document) {
    const std::uint64_t u64max = std::numeric_limits<std::uint64_t>::max();
    const std::vector<json> sizes = {0,
                                     1,
                                     3,
                                     255,
                                     std::uint64_t(1) << 31,
                                     (std::uint64_t(1) << 32) + 1,
                                     std::uint64_t(1) << 62,
                                     std::uint64_t(1) << 63,
                                     u64max,
                                     -1};
    const std::vector<json> indices = {-1, -5, 999, 2147483647};
    struct Field {
        const char* array;
        const char* key;
        const std::vector<json>* values;
    };
    const std::vector<json> componentTypes = {5120, 5121, 5122, 5123, 5125, 5126, 0, 9999};
    const std::vector<json> types = {"SCALAR", "VEC2", "VEC4", "MAT4", "BOGUS"};
    const Field fields[] = {
        {"accessors", "count", &sizes},
        {"accessors", "byteOffset", &sizes},
        {"accessors", "bufferView", &indices},
        {"accessors", "componentType", &componentTypes},
        {"accessors", "type", &types},
        {"bufferViews", "byteOffset", &sizes},
        {"bufferViews", "byteLength", &sizes},
        {"bufferViews", "byteStride", &sizes},
        {"bufferViews", "buffer", &indices},
        {"buffers", "byteLength", &sizes},
        {"skins", "inverseBindMatrices", &indices},
        {"nodes", "mesh", &indices},
        {"nodes", "skin", &indices},
    };
    std::vector<Mutant> out;
    for (const Field& field : fields) {
        if (!document.contains(field.array)) continue;
        const json& array = document[field.array];
        for (std::size_t i = 0; i < array.size(); ++i) {
            for (std::size_t v = 0; v < field.values->size(); ++v) {
                // Every value on the first element, then a rotating one per element: all values meet
                // many elements without multiplying the count.
                if (i > 0 && v != (i % field.values->size())) continue;
                json copy = document;
                copy[field.array][i][field.key] = (*field.values)[v];
                out.push_back({std::string(field.array) + "[" + std::to_string(i) + "]." + field.key + " = " +
                                   (*field.values)[v].dump(),
                               copy.dump()});
            }
        }
    }
    // Animation samplers and channels point at accessors and nodes.
    if (document.contains("animations")) {
        for (std::size_t a = 0; a < document["animations"].size(); ++a) {
            for (const char* key : {"input", "output"}) {
                for (const json& value : indices) {
                    json copy = document;
                    copy["animations"][a]["samplers"][0][key] = value;
                    out.push_back(
                        {"animations[" + std::to_string(a) + "].samplers[0]." + key + " = " + value.dump(),
                         copy.dump()});
                }
            }
            json copy = document;
            copy["animations"][a]["channels"][0]["target"]["node"] = 999;
            out.push_back({"animation channel target node 999", copy.dump()});
        }
    }
    json draco = document;
    draco["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    out.push_back({"extensionsRequired Draco", draco.dump()});
    return out;
}

}  // namespace mutation
