// A words file (base/words.hpp) on any bytes: parsed as a lesson's, every text filled and its
// placeholders listed, as the overlay and the tests use them.
#include "base/words.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    auto file = fx::parseWords(fuzz::text(data, size), "words.ja");
    if (!file) return 0;
    for (const auto& [key, text] : file->entries) {
        (void)fx::fillWords(text, {{"n", "1"}, {"asked", "6"}, {key, text}});
        (void)fx::WordsFile::placeholders(text);
    }
    return 0;
}
