// The scene reader (scene/scene_loader.hpp) on any bytes: a refusal or a scene, never a crash, a hang
// or a runaway allocation. Paths resolve against res/ as a shipped scene's do; files are not read, so
// an input costs the parser's time only.
#include "fuzz_input.hpp"
#include "scene/scene_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const fx::SceneLoadOptions options = [] {
        fx::SceneLoadOptions o;
        o.assetRoot = fx::projectRoot() / "res";
        o.checkFilesExist = false;
        return o;
    }();
    static const std::filesystem::path nominal = fx::projectRoot() / "res" / "scenes" / "fuzz.json";
    auto scene = fx::parseScene(fuzz::text(data, size), nominal, options);
    (void)scene;
    return 0;
}
