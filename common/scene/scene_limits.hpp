#pragma once
// What one scene file may ask for. A scene past a limit is refused with the limit named, before the
// loader spends time or memory on it; docs/scene-format.md lists the same numbers (a unit test keeps the
// two in step). The file's own size limit is file_limits::scene (base/file_io.hpp).
#include <cstddef>
#include <string>
#include <string_view>

namespace fx::scene_limits {

inline constexpr std::size_t kMaxObjects = 4096;
// As many as the GPU's point light list holds (kMaxGridLights, scene_light_grid.hpp): every light a
// lesson can draw, written as lights of their own or as grids (the two together have that limit).
inline constexpr std::size_t kMaxLights = 1024;
inline constexpr std::size_t kMaxLightGrids = 64;
inline constexpr std::size_t kMaxEmitters = 256;
inline constexpr std::size_t kMaxClouds = 16;
inline constexpr std::size_t kMaxClipsPerObject = 256;
// Vertices of glTF models over all objects: each object holds its own copy on the GPU (32 to 48 bytes a
// vertex), so this bounds the scene's mesh memory at about 400 MB. Checked when the models are read.
inline constexpr std::size_t kMaxDrawnVertices = std::size_t(1) << 23;
// Any string in the file (names, descriptions, paths, field names), in bytes.
inline constexpr std::size_t kMaxStringBytes = 4096;
// Objects and arrays inside one another.
inline constexpr std::size_t kMaxNesting = 32;
}  // namespace fx::scene_limits
