#include "scene/asset_path.hpp"

#include <system_error>

#include "base/log.hpp"
#include "base/message_text.hpp"
#include "scene/scene_limits.hpp"

namespace fx {
namespace {

namespace fs = std::filesystem;

// weakly_canonical resolves the links in the part of the path that exists, so a link inside the root
// that points outside it is caught. It only fails on odd file-system errors; the lexical form is then the
// best there is.
fs::path normalised(const fs::path& path) {
    std::error_code ec;
    fs::path result = fs::weakly_canonical(path, ec);
    if (ec) result = path.lexically_normal();
    // A trailing separator ("textures/") would make the path look like a folder inside the root.
    if (!result.has_filename()) result = result.parent_path();
    return result;
}

bool isInside(const fs::path& path, const fs::path& root) {
    auto pathPart = path.begin();
    for (auto rootPart = root.begin(); rootPart != root.end(); ++rootPart, ++pathPart) {
        if (rootPart->empty()) continue;  // a trailing separator on the root
        if (pathPart == path.end() || *pathPart != *rootPart) return false;
    }
    return pathPart != path.end();  // the root itself is not a file inside it
}

}  // namespace

Result<fs::path> resolveAssetPath(std::string_view written, const fs::path& sceneFolder,
                                  const fs::path& assetRoot) {
    if (written.empty()) return Error{"the path is empty"};
    if (written.find('\0') != std::string_view::npos) return Error{"the path contains a NUL character"};
    fs::path path(written);
    fs::path absolute = path.is_absolute() ? path : fs::absolute(sceneFolder) / path;
    fs::path resolved = normalised(absolute);
    fs::path root = normalised(fs::absolute(assetRoot));
    if (!isInside(resolved, root)) {
        return Error{cat("\"", excerpt(written), "\" resolves to ", resolved.string(),
                         ", which is outside the asset root ", root.string(),
                         " (scenes may only use files under it)")};
    }
    return resolved;
}

}  // namespace fx
