#include "gl/shader_substitutes.hpp"

#include <map>
#include <utility>

#include "base/paths.hpp"

namespace fx::gl {
namespace {

namespace fs = std::filesystem;

// One thread draws; the table is only read while programs build on it.
std::map<fs::path, fs::path>& substitutes() {
    static std::map<fs::path, fs::path> table;
    return table;
}

fs::path key(const fs::path& file) {
    return (file.is_absolute() ? file : shaderDir() / file).lexically_normal();
}

}  // namespace

ShaderSubstitute::ShaderSubstitute(const fs::path& original, const fs::path& replacement)
    : original_(key(original)) {
    auto& table = substitutes();
    if (auto it = table.find(original_); it != table.end()) before_ = it->second;
    table[original_] = fs::absolute(replacement).lexically_normal();
}

ShaderSubstitute::~ShaderSubstitute() {
    if (before_)
        substitutes()[original_] = *before_;
    else
        substitutes().erase(original_);
}

ShaderSubstitutesSetAside::ShaderSubstitutesSetAside() : set_(std::exchange(substitutes(), {})) {}

ShaderSubstitutesSetAside::~ShaderSubstitutesSetAside() {
    substitutes() = std::move(set_);
}

fs::path substitutedShaderFile(const fs::path& file) {
    const auto& table = substitutes();
    if (table.empty()) return file;
    auto it = table.find(key(file));
    return it != table.end() ? it->second : file;
}

std::vector<fs::path> shaderSubstituteFiles() {
    std::vector<fs::path> files;
    for (const auto& [original, replacement] : substitutes()) files.push_back(replacement);
    return files;
}

}  // namespace fx::gl
