// The parts of the file rule that are the same on every system; file_io_posix.cpp and file_io_win.cpp
// hold the reading and writing themselves.
#include "base/file_io.hpp"
#include "base/file_io_rules.hpp"

#include "base/log.hpp"

namespace fx {

namespace fs = std::filesystem;

namespace detail {

// Why `name` is not a name inside the folder (empty, absolute, climbing out with ".."), or nothing.
std::optional<std::string> outsideTheFolder(const fs::path& name) {
    if (name.empty()) return "no file name given";
    if (name.is_absolute()) return "an absolute path where a name inside the folder is expected";
    for (const fs::path& part : name)
        if (part == "..") return "\"..\" would leave the folder";
    if (!name.has_filename()) return "names a folder, not a file";
    return std::nullopt;
}

}  // namespace detail

std::string describeByteCount(std::size_t bytes) {
    if (bytes >= file_limits::kMiB && bytes % file_limits::kMiB == 0)
        return cat(bytes / file_limits::kMiB, " MiB");
    if (bytes >= 1024 && bytes % 1024 == 0) return cat(bytes / 1024, " KiB");
    return cat(bytes, " bytes");
}

Result<std::string> readTextFile(const fs::path& path) {
    return readFile(path, file_limits::text);
}

Status writeFileInFolder(const fs::path& folder, const fs::path& name, std::string_view text) {
    return writeFileInFolder(folder, name, std::as_bytes(std::span(text.data(), text.size())));
}

Status writeFileAtomically(const fs::path& path, std::span<const std::byte> bytes) {
    if (path.empty()) return Error{"cannot write a file with an empty name"};
    if (!path.has_filename()) return Error{cat(path.string(), ": is a folder; give a file name")};
    return writeFileInFolder(path.parent_path(), path.filename(), bytes);
}

Status writeFileAtomically(const fs::path& path, std::string_view text) {
    return writeFileAtomically(path, std::as_bytes(std::span(text.data(), text.size())));
}

bool namesStandardOutput(const fs::path& path) {
    return path.native().size() == 1 && path.native()[0] == '-';  // char or wchar_t
}

}  // namespace fx
