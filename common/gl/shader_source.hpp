#pragma once
// GLSL files with #include. The expanded text carries #line directives whose source-string number
// is the index of the file it came from, so a compiler message can be turned back into the real
// file name and line (mapCompilerLog), also inside included files.
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.hpp"

namespace fx::gl {

struct ExpandedSource {
    std::string text;                          // ready for glShaderSource
    std::vector<std::string> fileNames;        // index = source-string number in #line
    std::vector<std::filesystem::path> files;  // every file read, for reload on change
};

using FileReader = std::function<Result<std::string>(const std::filesystem::path&)>;

// Expands `#include "name"` recursively. A name resolves against the including file's folder
// first, then against `includeRoot`. Each file is included once per shader (later includes of the
// same file are skipped), a cycle is an error, and a missing file names the file and line of the
// #include. `defines` (lines like "#define FOO 1") go right after #version.
Result<ExpandedSource> expandShaderSource(const std::filesystem::path& file,
                                          const std::filesystem::path& includeRoot,
                                          std::string_view defines = {}, const FileReader& reader = {});

// Rewrites the source-string numbers in a compiler log (Mesa "0:12(5): error", NVIDIA
// "0(12) : error", AMD "ERROR: 0:12:") into "file:12:5: error" using the names of `fileNames`.
std::string mapCompilerLog(std::string_view log, const std::vector<std::string>& fileNames);

}  // namespace fx::gl
