// The glTF loader with tinygltf (scene/gltf_loader.hpp) on any bytes, as a .gltf document or a .glb
// (chosen by the bytes' header, as the loader does): a refusal or a model, never a crash. A refusal
// always says why: "without giving a reason" means a rule tinygltf refuses silently that the loader
// does not name yet (gltf_precheck.cpp), and is a finding.
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string>

#include "base/log.hpp"
#include "fuzz_input.hpp"
#include "scene/gltf_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const bool quiet = [] {
        fx::log::setConsoleLevel(fx::log::Level::error);  // a model's warnings, thousands a second
        return true;
    }();
    (void)quiet;
    static const std::filesystem::path models = fx::projectRoot() / "res" / "models";
    static const std::string noReason =
        (models / "fuzz.gltf").string() + ": tinygltf refused it without giving a reason";
    auto model = fx::parseGltfBytes(std::as_bytes(std::span(data, size)), models, models / "fuzz.gltf");
    if (!model && model.error() == noReason) {
        std::fprintf(stderr, "a refusal without a reason: %s\n", model.error().c_str());
        std::abort();
    }
    return 0;
}
