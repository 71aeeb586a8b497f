#pragma once
// The folder of an unpacked release the program runs from, for projectRoot() (base/paths.hpp):
// Windows: the .exe's folder when shaders/ and res/ are there (the zip); Linux: nothing, the build
// tree being the root (paths_posix.cpp, paths_win.cpp).
#include <filesystem>
#include <optional>

namespace fx {

std::optional<std::filesystem::path> installedRoot();

}  // namespace fx
