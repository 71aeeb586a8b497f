#pragma once
// The files a glTF document names (its buffers' and images' URIs), read by fxlab before tinygltf sees
// the document, under the rule for every path a file names (base/path_rule.hpp): a URI is decoded as
// tinygltf decodes it (%2e%2e is ".."), resolved against the model's folder with its links followed,
// and must stay inside the asset root that holds the model (or the model's own folder, for a model
// outside every asset root); what it names is read with fxlab's reader (regular files only,
// never a blocking open of a FIFO, within the glTF size limit). tinygltf is then given these bytes
// alone through its file callbacks, so it never opens a file itself.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.hpp"

namespace fx {

struct GltfFiles {
    std::filesystem::path modelFolder;                        // resolved
    std::map<std::string, std::vector<unsigned char>> bytes;  // by resolved path
    std::map<std::string, std::string> unreadImages;          // resolved path -> why (a warning)
    std::vector<std::string> warnings;                        // fxlab's words for unreadImages
};

// As tinygltf decodes a URI before it opens it: %XX is the byte XX, '+' a space.
std::string decodeGltfUri(std::string_view uri);

// Reads every external file `document` names. A URI that leaves the model's folder, names something
// that is not a regular file, or a buffer that cannot be read is refused: "buffers[0].uri: ..."; an
// image that cannot be read is a warning (the material goes without it). A document that is not JSON
// gives no files (tinygltf words its syntax error itself).
// `root` is the folder the files must stay in: the asset root holding the model, or the model's own.
Result<GltfFiles> readGltfFiles(std::string_view document, const std::filesystem::path& modelFolder,
                                const std::filesystem::path& root);

// The resolved path tinygltf asks for, as readGltfFiles keys it.
std::string gltfFileKey(const std::string& path);

}  // namespace fx
