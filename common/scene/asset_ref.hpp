#pragma once
// A file a scene refers to (a glTF model, a texture). The scene keeps the path as written, so saving
// writes back what the author wrote, and the resolved path, which is what the renderer opens.
#include <filesystem>
#include <string>

namespace fx {

struct AssetRef {
    std::string path;                // as written in the scene file, relative to that file
    std::filesystem::path resolved;  // absolute and normalised; inside the asset root

    bool empty() const { return path.empty(); }
    bool operator==(const AssetRef&) const = default;
};

}  // namespace fx
