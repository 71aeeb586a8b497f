#include "assetgen.hpp"

#include "base/file_io.hpp"
#include "base/log.hpp"
#include "image/png_file.hpp"
#include "textures.hpp"

namespace fx::assetgen {
namespace {

std::vector<std::byte> textBytes(const std::string& text) {
    const auto* p = reinterpret_cast<const std::byte*>(text.data());
    return {p, p + text.size()};
}

void addModel(std::vector<GeneratedFile>& files, const std::string& name, const GeneratedModel& model) {
    files.push_back({"models/" + name + ".gltf", textBytes(model.gltf)});
    files.push_back({"models/" + name + ".bin", model.bin});
}

void addTexture(std::vector<GeneratedFile>& files, const std::string& name, const ByteImage& image) {
    auto png = encodePng(image);
    // encodePng fails only for an empty or malformed image, which these generators never make.
    files.push_back({"textures/" + name + ".png", png ? *png : std::vector<std::byte>{}});
    if (!png) log::error("textures/", name, ".png: ", png.error());
}

}  // namespace

std::vector<GeneratedFile> generateAssets() {
    std::vector<GeneratedFile> files;
    addModel(files, "character", makeCharacter());
    addModel(files, "crate", makeCrate());
    addModel(files, "lantern", makeLantern());
    addModel(files, "ground", makeGround());
    addTexture(files, "ground_checker", groundChecker());
    addTexture(files, "cloud_density", cloudDensity());
    addTexture(files, "fire_sprite", fireSprite());
    addTexture(files, "crate_planks", cratePlanks());
    addTexture(files, "suit_fabric", suitFabric());
    addTexture(files, "cutout_lattice", cutoutLattice());
    return files;
}

Status writeAssets(const std::filesystem::path& root) {
    return writeAssets(root, generateAssets());
}

Status writeAssets(const std::filesystem::path& root, const std::vector<GeneratedFile>& files) {
    for (const GeneratedFile& file : files) {
        if (file.bytes.empty()) return Error{cat(file.path, ": nothing was generated")};
        if (auto written = writeFileInFolder(root, file.path, std::span<const std::byte>(file.bytes));
            !written)
            return written;
    }
    return Status::success();
}

}  // namespace fx::assetgen
