#pragma once
// Rules of glTF 2.0 that tinygltf refuses without a reason, or with a reason that hides the rule,
// checked on the document before tinygltf reads it, so that the refusal names the rule: a skin without
// "joints" (tinygltf: no reason at all), geometry compressed with Draco and no uncompressed copy
// (tinygltf: "accessor[N] invalid bufferView").
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace fx {

// The JSON chunk of a binary glTF (.glb), or nothing when `bytes` do not start with a .glb header whose
// first chunk is JSON and fits in the file (tinygltf then words what is wrong).
std::optional<std::string_view> glbJsonChunk(std::span<const std::byte> bytes);
bool isGlb(std::span<const std::byte> bytes);

// The first rule `document` (a .gltf's text or a .glb's JSON chunk) breaks, worded for a message
// ("skin 0 'rig': has no \"joints\" ..."), or nothing when it breaks none of them or is not JSON at all
// (tinygltf words syntax errors itself).
std::optional<std::string> findUnnamedGltfRefusal(std::string_view document);

}  // namespace fx
