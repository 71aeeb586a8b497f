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

// The files the model names (its buffers' and images' URIs) stay inside the asset root that holds the
// model (`assetRoot`, the default one when empty), or, for a model outside it, inside the model's own
// folder (scene/gltf_files.hpp).
Result<GltfModel> loadGltf(const std::filesystem::path& file, const std::filesystem::path& assetRoot = {});

// The same from text in memory (a .gltf document); relative URIs resolve against `baseDir`.
Result<GltfModel> parseGltf(const std::string& json, const std::filesystem::path& baseDir,
                            const std::filesystem::path& nominalFile = "memory.gltf");

// The same from a file's bytes in memory: a binary glTF (.glb) when they start with its header, else a
// .gltf document. Messages name `nominalFile`. The files it names stay inside `root` (`baseDir` when
// empty).
Result<GltfModel> parseGltfBytes(std::span<const std::byte> bytes, const std::filesystem::path& baseDir,
                                 const std::filesystem::path& nominalFile,
                                 const std::filesystem::path& root = {});

// Smooth per-vertex normals from the triangles (area-weighted). A vertex that belongs to no
// triangle, or only to degenerate ones, gets +Y rather than a NaN from normalising zero.
void computeNormals(MeshData& mesh);

}  // namespace fx
