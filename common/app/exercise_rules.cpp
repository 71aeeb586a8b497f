#include "app/exercise_rules.hpp"

#include <cerrno>
#include <cstring>

#include <sys/stat.h>

#include "app/exercise_catalog.hpp"
#include "base/log.hpp"
#include "base/path_rule.hpp"

namespace fx {

namespace fs = std::filesystem;

std::optional<std::string> whyNotAStudentsFile(const fs::path& file) {
    struct stat link {};
    if (::lstat(file.c_str(), &link) != 0) return std::nullopt;  // missing: the check says how to start
    struct stat st {};
    if (::stat(file.c_str(), &st) != 0)
        return cat(file.string(), ": a symbolic link to nothing (", std::strerror(errno),
                   "); your work goes in a regular file");
    std::string what;
    if (S_ISREG(st.st_mode)) return std::nullopt;
    if (S_ISDIR(st.st_mode))
        what = "a folder";
    else if (S_ISFIFO(st.st_mode))
        what = "a FIFO (named pipe)";
    else if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode))
        what = "a device";
    else if (S_ISSOCK(st.st_mode))
        what = "a socket";
    else
        what = "not a regular file";
    if (S_ISLNK(link.st_mode)) {
        std::error_code ec;
        what = cat("a symbolic link to ", what, " (", fs::read_symlink(file, ec).string(), ")");
    }
    return cat(file.string(), ": is ", what,
               ", not a file; your work goes in a regular file (it is not read)");
}

std::optional<std::string> whyNotTheStudentsOwn(const fs::path& file) {
    const fs::path answers = resolvedPath(exerciseRoot() / "solutions");
    const fs::path resolved = resolvedPath(fs::absolute(file));
    if (!isInsideFolder(resolved, answers)) return std::nullopt;
    return cat(file.string(), ": resolves to ", resolved.string(), ", one of the exercises' answers (",
               answers.string(), "); the check grades only your own file");
}

}  // namespace fx
