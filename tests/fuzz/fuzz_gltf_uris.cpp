// The URIs of a glTF file's buffers and images (scene/gltf_files.hpp): the input's first line is a
// buffer's URI, the rest an image's, in a document loaded from a model folder that holds a file, a FIFO,
// a link out of the folder and a link to /dev/zero. Whatever the URI, the load returns (a FIFO is never
// opened to be read: libFuzzer's -timeout catches a hang) and every file read lies inside the folder;
// a file read from outside it is a finding.
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "base/json_text.hpp"
#include "base/log.hpp"
#include "base/path_rule.hpp"
#include "fuzz_input.hpp"
#include "scene/gltf_files.hpp"
#include "scene/gltf_loader.hpp"

namespace {

namespace fs = std::filesystem;

// The model's folder and what lies around it, made once a process.
fs::path modelFolder() {
    static const fs::path folder = [] {
        const fs::path root = fs::temp_directory_path() / ("fx_fuzz_gltf_uris_" + std::to_string(::getpid()));
        fs::remove_all(root);
        fs::create_directories(root / "model" / "sub");
        for (const fs::path& file :
             {root / "outside.bin", root / "model" / "inside.bin", root / "model" / "sub" / "a.png"}) {
            std::FILE* f = std::fopen(file.c_str(), "wb");
            std::fwrite("abcd", 1, 4, f);
            std::fclose(f);
        }
        ::mkfifo((root / "model" / "pipe.bin").c_str(), 0600);
        ::mkfifo((root / "pipe-outside").c_str(), 0600);
        fs::create_symlink(root / "outside.bin", root / "model" / "link.bin");
        fs::create_symlink(root / "pipe-outside", root / "model" / "link-pipe.bin");
        fs::create_symlink("/dev/zero", root / "model" / "zero.bin");
        std::atexit([] {
            fs::remove_all(fs::temp_directory_path() / ("fx_fuzz_gltf_uris_" + std::to_string(::getpid())));
        });
        return root / "model";
    }();
    return folder;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const bool quiet = [] {
        fx::log::setConsoleLevel(fx::log::Level::error);
        return true;
    }();
    (void)quiet;
    const fs::path folder = modelFolder();
    const std::string input(fuzz::text(data, size));
    const std::size_t cut = input.find('\n');
    const std::string buffer = input.substr(0, cut);
    const std::string image = cut == std::string::npos ? "" : input.substr(cut + 1);
    nlohmann::json doc = {{"asset", {{"version", "2.0"}}}};
    doc["buffers"] = {{{"uri", buffer}, {"byteLength", 4}}};
    if (!image.empty()) doc["images"] = {{{"uri", image}}};
    const std::string text = fx::dumpJson(doc);

    auto files = fx::readGltfFiles(text, folder, folder);
    if (files) {
        for (const auto& [path, bytes] : files->bytes) {
            if (!fx::isInsideFolder(fx::resolvedPath(path), fx::resolvedPath(folder))) {
                std::fprintf(stderr, "read from outside the model's folder: %s\n", path.c_str());
                std::abort();
            }
        }
    }
    (void)fx::parseGltfBytes(std::as_bytes(std::span(text.data(), text.size())), folder,
                             folder / "fuzz.gltf");
    return 0;
}
