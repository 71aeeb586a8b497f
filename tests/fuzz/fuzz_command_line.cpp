// A lesson's command line (app/run_options.hpp) on any bytes, split into arguments at NUL bytes: a
// refusal or options, never a crash; a refusal quotes what the user typed at a readable length.
#include <cstdlib>
#include <string>
#include <vector>

#include "app/run_options.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> args(1);
    for (char c : fuzz::text(data, size)) {
        if (c == '\0')
            args.emplace_back();
        else
            args.back() += c;
    }
    auto options = fx::parseRunOptions(args, 5);
    // Messages quote at most 48 bytes of a value (escaped, up to 6 bytes a byte) and a flag's name.
    if (!options && options.error().size() > 2000) std::abort();
    return 0;
}
