#pragma once
// What a lesson run was asked to do, from its command line. Parsing is separate from running so
// that every flag and every error message has a unit test.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "base/timing_mode.hpp"

namespace fx {

struct RunOptions {
    bool help = false;
    bool listSteps = false;
    bool listParams = false;
    bool forceHeadless = false;
    std::optional<int> width, height;     // --size WxH
    std::optional<int> frames;            // --frames N (default: 3 headless, until closed in a window)
    std::optional<int> step;              // --step K, 1-based
    std::filesystem::path scene;          // --scene FILE
    std::filesystem::path captureDir;     // --capture DIR
    bool captureFloat = false;            // --capture-float
    std::filesystem::path reportFile;     // --report FILE
    std::optional<double> timeStep;       // --time-step S (fixed step; default 1/60 s headless)
    std::uint32_t seed = 1;               // --seed N
    std::vector<std::string> params;      // --param name=value, checked once the lesson is known
    std::filesystem::path presetFile;     // --preset FILE
    TimingMode timing = TimingMode::Automatic;  // --timing gpu|fenced|off
    bool overlay = true;                  // --no-overlay; headless draws it only with --overlay
    bool overlayHeadless = false;         // --overlay
    std::vector<std::string> inspect;     // --inspect NAME: keep a texture and its producers alive
    bool bench = false;                   // --bench: sweep the quality knobs instead of running
    std::string benchKnob;                // --knob NAME: only this knob
    int benchFrames = 5;                  // --bench-frames N: measured frames per setting
    int benchValues = 0;                  // --bench-values N: only the first N values of each knob
    std::filesystem::path benchOut;       // --bench-out DIR (default out/bench/<NN-name>)
    std::string language = "en";          // --lang en|ja: the lesson text's language
};

// Errors name the flag and what it takes: "--size: expected WxH with sizes from 0 to 16384, got 12".
Result<RunOptions> parseRunOptions(const std::vector<std::string>& args);

std::string runOptionsHelp(const std::string& program);

}  // namespace fx
