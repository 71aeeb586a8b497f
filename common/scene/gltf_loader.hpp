#pragma once
// Reads a glTF 2.0 file (.gltf with its .bin, or .glb) into a GltfModel, through tinygltf. A bad
// file comes back as an error that names the file and what is wrong ("mesh 'body' primitive 0:
// index 812 is beyond the 800 vertices"); nothing throws and nothing is left half-loaded. Features
// fxlab does not draw (morph targets, cameras, lights, lines and points) are skipped with a warning.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>

#include "base/result.hpp"
#include "scene/gltf_model.hpp"

namespace fx {

Result<GltfModel> loadGltf(const std::filesystem::path& file);

// The same from text in memory (a .gltf document); relative URIs resolve against `baseDir`.
Result<GltfModel> parseGltf(const std::string& json, const std::filesystem::path& baseDir,
                            const std::filesystem::path& nominalFile = "memory.gltf");

// The same from a file's bytes in memory: a binary glTF (.glb) when they start with its header, else a
// .gltf document. Messages name `nominalFile`.
Result<GltfModel> parseGltfBytes(std::span<const std::byte> bytes, const std::filesystem::path& baseDir,
                                 const std::filesystem::path& nominalFile);

// Smooth per-vertex normals from the triangles (area-weighted). A vertex that belongs to no
// triangle, or only to degenerate ones, gets +Y rather than a NaN from normalising zero.
void computeNormals(MeshData& mesh);

}  // namespace fx
