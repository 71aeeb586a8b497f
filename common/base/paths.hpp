#pragma once
// Where fxlab finds its shaders and resources at run time: the source tree it was built from,
// unless FXLAB_ROOT in the environment names another checkout, or the program runs from an unpacked
// release (Windows' zip: base/installed_root.hpp).
#include <filesystem>

namespace fx {

std::filesystem::path projectRoot();
std::filesystem::path shaderDir();    // <root>/shaders
std::filesystem::path resourceDir();  // <root>/res

}  // namespace fx
