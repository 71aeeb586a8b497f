#pragma once
// The one rule for a path that a file names (a scene's texture, a glTF file's buffer or image, a
// lesson text's picture, a shader's #include): it is resolved against the folder of the file that names
// it, normalised, its symbolic links followed as far as they exist, and it must then lie inside one of
// the roots the caller allows and inside none of the ones it forbids. However it is spelt ("..",
// absolute, a link, %2e%2e once a URI is decoded), a path that leaves its roots is refused, the
// refusal saying where it resolved and which root it left; the caller adds the file and the field or
// line where the path was written.
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "base/result.hpp"

namespace fx {

// A folder in a rule, and what it is called in the refusal ("the asset root", "the model's folder").
struct PathRoot {
    std::filesystem::path folder;
    std::string_view called;
};

// `written` resolved against `base` (absolute paths stay as they are), inside one of `allowed` and none
// of `forbidden`; an error reads
//   "../x.png" resolves to /etc/x.png, which is outside the model's folder /a/m (<why>)
//   "../s.glsl" resolves to /p/exercises/solutions/05-1/s.glsl, inside the exercises' answers /p/... (<why>)
// with `why` the rule's reason in the caller's words.
Result<std::filesystem::path> resolveInsideRoots(std::string_view written, const std::filesystem::path& base,
                                                 std::span<const PathRoot> allowed,
                                                 std::span<const PathRoot> forbidden, std::string_view why);

// The path with its links followed as far as it exists, normalised, with no trailing separator.
std::filesystem::path resolvedPath(const std::filesystem::path& path);
// Whether `path` lies strictly inside `root` (both resolved).
bool isInsideFolder(const std::filesystem::path& path, const std::filesystem::path& root);

}  // namespace fx
