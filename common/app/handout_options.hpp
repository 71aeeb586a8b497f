#pragma once
// The command line of fxlab-handout (`./fxlab handout` passes the lesson executables it found):
//   fxlab-handout [--lang en|ja|en,ja] [--out DIR] [--force] [--with-bench] [--bench-dir DIR]
//                 [--size WxH] [--frames N] LESSON_EXECUTABLE...
// One lesson writes its folder at DIR (default out/handouts/NN-name); several write DIR (default
// out/handouts) with a contents page and one folder per lesson. Parsed apart from running, so each
// error message has a unit test.
#include <filesystem>
#include <string>
#include <vector>

#include "app/handout_build.hpp"
#include "base/result.hpp"

namespace fx::handout {

struct CommandLine {
    HandoutOptions options;
    std::filesystem::path out;  // empty: the default for one lesson or several
    bool force = false;
    bool help = false;
    std::vector<std::filesystem::path> lessons;
};

Result<CommandLine> parseCommandLine(const std::vector<std::string>& args);

// Where the handout goes when --out is not given.
std::filesystem::path defaultOut(const CommandLine& line);

std::string usage();

}  // namespace fx::handout
