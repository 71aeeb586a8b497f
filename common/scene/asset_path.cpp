#include "scene/asset_path.hpp"

#include "base/path_rule.hpp"

namespace fx {

namespace fs = std::filesystem;

Result<fs::path> resolveAssetPath(std::string_view written, const fs::path& sceneFolder,
                                  const fs::path& assetRoot) {
    const PathRoot root{assetRoot, "the asset root"};
    return resolveInsideRoots(written, sceneFolder, std::span(&root, 1), {},
                              "scenes may only use files under it");
}

}  // namespace fx
