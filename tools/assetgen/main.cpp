// fxlab-assetgen: writes the generated models and textures (res/models, res/textures).
//   fxlab-assetgen               writes into <repo>/res
//   fxlab-assetgen --out DIR     writes into DIR/models and DIR/textures
// The output is the same bytes on every run; tests/unit/assetgen compares it with the committed files.
#include <cstring>
#include <iostream>

#include "assetgen.hpp"
#include "base/fatal_error.hpp"
#include "base/paths.hpp"

int main(int argc, char** argv) {
    fx::installFatalErrorHandler("fxlab-assetgen");
    std::filesystem::path out = fx::resourceDir();
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--out") == 0 && i + 1 < argc) {
            out = argv[++i];
        } else {
            std::cerr << "usage: " << argv[0] << " [--out DIR]\n";
            return 2;
        }
    }
    auto files = fx::assetgen::generateAssets();
    std::size_t bytes = 0;
    for (const auto& file : files) bytes += file.bytes.size();
    if (auto written = fx::assetgen::writeAssets(out, files); !written) {
        std::cerr << "fxlab-assetgen: " << written.error() << "\n";
        return 1;
    }
    std::cout << "fxlab-assetgen: wrote " << files.size() << " files (" << bytes << " bytes) under "
              << out.string() << "\n";
    return 0;
}
