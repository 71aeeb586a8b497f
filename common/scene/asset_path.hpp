#pragma once
// Where a path written in a scene file points, and the rule that keeps it inside the asset root: a scene
// may name only files under the root, however its path is spelt ("..", absolute, symbolic links).
#include <filesystem>
#include <string_view>

#include "base/result.hpp"

namespace fx {

// Resolves `written` against `sceneFolder` (absolute paths stay as they are), normalises it, follows the
// symbolic links that exist, and refuses a result outside `assetRoot`. The error says why, without the
// scene file's name (the caller adds where the path was written).
Result<std::filesystem::path> resolveAssetPath(std::string_view written,
                                               const std::filesystem::path& sceneFolder,
                                               const std::filesystem::path& assetRoot);

}  // namespace fx
