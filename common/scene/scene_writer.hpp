#pragma once
// Writes a scene back to scene-file JSON. Loading the text again (from the same folder, since paths are
// written as they were read) gives an equal Scene: parseScene(saveScene(s), s.file) == s for any scene
// the loader accepts. Fields a light type, shape or motion does not use are not written.
#include <string>

#include "scene/scene.hpp"

namespace fx {

std::string saveScene(const Scene& scene);

}  // namespace fx
