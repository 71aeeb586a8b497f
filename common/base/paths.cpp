#include "base/paths.hpp"

#include <cstdlib>

namespace fx {

std::filesystem::path projectRoot() {
    if (const char* env = std::getenv("FXLAB_ROOT"); env != nullptr && *env != '\0') return env;
    return FXLAB_SOURCE_ROOT;
}

std::filesystem::path shaderDir() {
    return projectRoot() / "shaders";
}
std::filesystem::path resourceDir() {
    return projectRoot() / "res";
}

}  // namespace fx
