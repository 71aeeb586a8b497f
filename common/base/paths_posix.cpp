#include "base/installed_root.hpp"

namespace fx {

// Linux runs from the tree it was built in (FXLAB_SOURCE_ROOT) or from FXLAB_ROOT.
std::optional<std::filesystem::path> installedRoot() {
    return std::nullopt;
}

}  // namespace fx
