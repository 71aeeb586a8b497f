// Replays fuzz inputs through a fuzz target in the normal build (no libFuzzer): every file named, and
// every file in every folder named, once. The inputs libFuzzer found are kept as regression tests
// (tests/fuzz/regressions/<target>/) and run this way in the normal and the sanitizer suites, with the
// shipped seeds. Prints how many inputs ran; a crash or an abort fails the test.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "base/file_io.hpp"
#include "fuzz_input.hpp"

int main(int argc, char** argv) {
    namespace fs = std::filesystem;
    std::vector<fs::path> inputs;
    for (int i = 1; i < argc; ++i) {
        const fs::path arg = argv[i];
        if (fs::is_directory(arg)) {
            for (const auto& entry : fs::recursive_directory_iterator(arg))
                if (entry.is_regular_file()) inputs.push_back(entry.path());
        } else {
            inputs.push_back(arg);
        }
    }
    std::sort(inputs.begin(), inputs.end());
    int ran = 0;
    for (const fs::path& input : inputs) {
        auto bytes = fx::readFile(input, fx::file_limits::text);
        if (!bytes) {
            std::fprintf(stderr, "%s\n", bytes.error().c_str());
            return 1;
        }
        LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes->data()), bytes->size());
        ++ran;
    }
    std::printf("%d inputs replayed\n", ran);
    return ran > 0 ? 0 : 1;
}
