#include "scene/gltf_files.hpp"

#include <cerrno>

#include <sys/stat.h>
#include <nlohmann/json.hpp>

#include "base/file_io.hpp"
#include "base/log.hpp"
#include "base/message_text.hpp"
#include "base/path_rule.hpp"

namespace fx {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kRule =
    "a glTF file may only name files in its own folder or below it, or elsewhere in the asset root that holds it";

bool isDataUri(std::string_view uri) {
    return uri.substr(0, 5) == "data:";
}

unsigned char hexValue(unsigned char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return 0;  // as tinygltf reads a bad digit
}

}  // namespace

std::string decodeGltfUri(std::string_view uri) {
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+') {
            out += ' ';
        } else if (uri[i] == '%' && uri.size() > i + 2) {
            out += char((hexValue(uri[i + 1]) << 4) | hexValue(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

std::string gltfFileKey(const std::string& path) {
    return resolvedPath(fs::absolute(path)).string();
}

Result<GltfFiles> readGltfFiles(std::string_view document, const fs::path& modelFolder,
                                const fs::path& rootFolder) {
    GltfFiles files;
    files.modelFolder = resolvedPath(fs::absolute(modelFolder));
    const nlohmann::json j = nlohmann::json::parse(document, nullptr, false);
    if (j.is_discarded() || !j.is_object()) return files;
    const fs::path folder = resolvedPath(fs::absolute(rootFolder));
    const PathRoot root{folder, folder == files.modelFolder ? "the model's folder" : "the asset root"};
    for (const char* kind : {"buffers", "images"}) {
        const bool buffer = std::string_view(kind) == "buffers";
        auto list = j.find(kind);
        if (list == j.end() || !list->is_array()) continue;
        for (std::size_t i = 0; i < list->size(); ++i) {
            const nlohmann::json& entry = (*list)[i];
            if (!entry.is_object()) continue;
            auto uri = entry.find("uri");
            if (uri == entry.end() || !uri->is_string()) continue;
            const std::string& written = uri->get_ref<const std::string&>();
            if (written.empty() || isDataUri(written)) continue;
            const std::string field = cat(kind, "[", i, "].uri");
            auto path =
                resolveInsideRoots(decodeGltfUri(written), files.modelFolder, std::span(&root, 1), {}, kRule);
            if (!path) return Error{cat(field, ": ", path.error())};
            if (files.bytes.contains(path->string())) continue;
            struct stat st {};
            const bool missing = ::stat(path->c_str(), &st) != 0 && errno == ENOENT;
            auto bytes = missing ? Result<std::string>(Error{cat(path->string(), ": no such file")})
                                 : readFile(*path, file_limits::gltf);
            if (!bytes) {
                // A buffer holds the geometry: without it there is no model. An image is a material's
                // texture, which the material does without (drawn white), as a scene's does.
                if (buffer || !missing)
                    return Error{cat(field, " \"", excerpt(written), "\": ", bytes.error())};
                files.unreadImages[path->string()] = bytes.error();
                files.warnings.push_back(cat(field, " \"", excerpt(written), "\": ", bytes.error(),
                                             "; the material goes without this image"));
                continue;
            }
            files.bytes[path->string()].assign(bytes->begin(), bytes->end());
        }
    }
    return files;
}

}  // namespace fx
