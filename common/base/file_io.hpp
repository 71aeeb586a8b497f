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

// The one rule for every file fxlab writes (docs/reliability.md, "Every file written"):
//  - The file is written to a temporary file beside it and renamed over the target, so it is complete
//    or not there at all; on failure nothing is left at the target or beside it.
//  - Only a regular file (or nothing) at the target is replaced. A symbolic link (working or dangling),
//    a folder, a device, a FIFO or a socket there is refused with a message naming it; nothing is
//    written through it and it stays as it was.
//  - Nothing outside the chosen folder is touched: `folder` (the one the user or the program chose) is
//    created if missing and may be reached through links the user named, but every name below it
//    (`name` may go through subfolders: "step-2/final.png") is a real folder or file inside it, never a
//    link, and `name` may not climb out ("..") or be absolute.
// Messages carry the path and the system's reason.
Status writeFileInFolder(const std::filesystem::path& folder, const std::filesystem::path& name,
                         std::span<const std::byte> bytes);
Status writeFileInFolder(const std::filesystem::path& folder, const std::filesystem::path& name,
                         std::string_view text);
// writeFileInFolder with the path's own folder as the chosen one: `path`'s last name is the file.
Status writeFileAtomically(const std::filesystem::path& path, std::span<const std::byte> bytes);
Status writeFileAtomically(const std::filesystem::path& path, std::string_view text);
// Makes `name` (a folder below `folder`) under the same rule, for a program that writes there later
// (the --all-steps runs' DIR/step-K): a link or a file in the way is refused.
Status makeFolderIn(const std::filesystem::path& folder, const std::filesystem::path& name);

// "-" as an output path: the text goes to standard output instead of a file (--report -, --graph -).
bool namesStandardOutput(const std::filesystem::path& path);
Status writeStandardOutput(std::string_view text);

}  // namespace fx
