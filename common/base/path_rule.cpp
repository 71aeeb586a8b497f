#include "base/path_rule.hpp"

#include <system_error>

#include "base/log.hpp"
#include "base/message_text.hpp"

namespace fx {

namespace fs = std::filesystem;

// weakly_canonical resolves the links in the part of the path that exists, so a link inside the root
// that points outside it is caught. It only fails on odd file-system errors; the lexical form is then the
// best there is.
fs::path resolvedPath(const fs::path& path) {
    std::error_code ec;
    fs::path result = fs::weakly_canonical(path, ec);
    if (ec) result = path.lexically_normal();
    // A trailing separator ("textures/") would make the path look like a folder inside the root.
    if (!result.has_filename()) result = result.parent_path();
    return result;
}

bool isInsideFolder(const fs::path& path, const fs::path& root) {
    auto pathPart = path.begin();
    for (auto rootPart = root.begin(); rootPart != root.end(); ++rootPart, ++pathPart) {
        if (rootPart->empty()) continue;  // a trailing separator on the root
        if (pathPart == path.end() || *pathPart != *rootPart) return false;
    }
    return pathPart != path.end();  // the root itself is not a file inside it
}

Result<fs::path> resolveInsideRoots(std::string_view written, const fs::path& base,
                                    std::span<const PathRoot> allowed, std::span<const PathRoot> forbidden,
                                    std::string_view why) {
    if (written.empty()) return Error{"the path is empty"};
    if (written.find('\0') != std::string_view::npos) return Error{"the path contains a NUL character"};
    const fs::path path(written);
    const fs::path resolved = resolvedPath(path.is_absolute() ? path : fs::absolute(base) / path);
    for (const PathRoot& root : forbidden) {
        const fs::path folder = resolvedPath(fs::absolute(root.folder));
        if (resolved == folder || isInsideFolder(resolved, folder))
            return Error{cat("\"", excerpt(written), "\" resolves to ", resolved.string(), ", inside ",
                             root.called, " ", folder.string(), " (", why, ")")};
    }
    std::string roots;
    for (const PathRoot& root : allowed) {
        const fs::path folder = resolvedPath(fs::absolute(root.folder));
        if (isInsideFolder(resolved, folder)) return resolved;
        roots += cat(roots.empty() ? "" : " or ", root.called, " ", folder.string());
    }
    return Error{cat("\"", excerpt(written), "\" resolves to ", resolved.string(), ", which is outside ",
                     roots, " (", why, ")")};
}

}  // namespace fx
