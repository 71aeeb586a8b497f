#pragma once
// Every file the generator writes, as bytes, and writing them under a resource root. The same bytes on
// every run: no clock, no random device, integer hashes for noise, floats snapped before storing.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "base/result.hpp"

namespace fx::assetgen {

struct GeneratedFile {
    std::string path;  // relative to res/, with forward slashes: "models/character.gltf"
    std::vector<std::byte> bytes;
};

// A glTF document and its buffer.
struct GeneratedModel {
    std::string gltf;
    std::vector<std::byte> bin;
};

// The skinned character (17 joints, clips "walk" and "idle"), built from capsules and boxes.
GeneratedModel makeCharacter();
// A wooden crate (a textured box).
GeneratedModel makeCrate();
// A lantern on a post: a small node hierarchy with an HDR emissive lamp.
GeneratedModel makeLantern();
// A 20 m x 20 m ground plane with the checker texture repeated, 32-bit indices.
GeneratedModel makeGround();

// Everything, in a fixed order.
std::vector<GeneratedFile> generateAssets();

// Writes the files under `root` (res/ or a test folder), each atomically.
Status writeAssets(const std::filesystem::path& root, const std::vector<GeneratedFile>& files);
// Generates and writes everything.
Status writeAssets(const std::filesystem::path& root);

}  // namespace fx::assetgen
