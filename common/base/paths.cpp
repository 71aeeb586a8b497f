#include "base/paths.hpp"
#include "base/installed_root.hpp"
#include "base/utf8_path.hpp"

#include <cstdlib>

namespace fx {

std::filesystem::path projectRoot() {
    if (const char* env = std::getenv("FXLAB_ROOT"); env != nullptr && *env != '\0') return pathFromUtf8(env);
    if (auto installed = installedRoot()) return *installed;
    return FXLAB_SOURCE_ROOT;
}

std::filesystem::path shaderDir() {
    return projectRoot() / "shaders";
}
std::filesystem::path resourceDir() {
    return projectRoot() / "res";
}

}  // namespace fx
