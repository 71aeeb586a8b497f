#pragma once
// Reading whole files with a size limit, and writing them atomically: a file is either written
// completely or left as it was (write to a temporary file in the same folder, then rename over the
// target).
//
// Reads accept only regular files (after following symbolic links): a folder, a FIFO or a device is
// refused with a message saying what it is, and is never read (a FIFO without a writer cannot hang the
// read, /dev/zero cannot fill memory). Each kind of file has its own documented size limit, and a
// refusal names the kind and the limit ("scene file: 20000000 bytes is over the limit of 16 MiB").
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "base/result.hpp"

namespace fx {

// What a file is read as, and the most bytes such a file may have.
struct FileLimit {
    std::string_view kind;  // "scene file", "shader", ...
    std::size_t maxBytes;
};

namespace file_limits {
inline constexpr std::size_t kMiB = std::size_t(1) << 20;
inline constexpr FileLimit scene{"scene file", 16 * kMiB};
inline constexpr FileLimit shader{"shader", 4 * kMiB};
inline constexpr FileLimit preset{"preset", 1 * kMiB};
inline constexpr FileLimit png{"PNG image", 256 * kMiB};
inline constexpr FileLimit pfm{"PFM image", 1024 * kMiB};
inline constexpr FileLimit gltf{"glTF file", 512 * kMiB};  // .gltf, .glb, .bin and images it names
inline constexpr FileLimit text{"file", 64 * kMiB};        // anything else
}  // namespace file_limits

// "16 MiB", "512 KiB", "300 bytes": a limit as a person reads it.
std::string describeByteCount(std::size_t bytes);

Result<std::string> readFile(const std::filesystem::path& path, FileLimit limit);
// readFile with file_limits::text.
Result<std::string> readTextFile(const std::filesystem::path& path);

// Creates missing parent folders. On failure nothing is left at `path` or beside it, and the message
// carries the system's reason.
//  - A regular file (or nothing) at `path` is replaced atomically. A symbolic link is followed: its
//    target is replaced and the link stays a link.
//  - A folder is refused.
//  - Anything else (a device such as /dev/null, a FIFO, /dev/stdout) is written through, never
//    replaced; a FIFO nobody reads is refused instead of blocking.
//  - Paths naming this process's open files (/dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N) are
//    always written through, appending, so `--report /dev/stdout > r.json` writes into r.json.
Status writeFileAtomically(const std::filesystem::path& path, std::span<const std::byte> bytes);
Status writeFileAtomically(const std::filesystem::path& path, std::string_view text);

}  // namespace fx
