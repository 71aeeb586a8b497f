#pragma once
// What a lesson run was asked to do, from its command line. Parsing is separate from running so
// that every flag and every error message has a unit test. One table of flags (run_options.cpp)
// drives both the parser and --help.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/window_input.hpp"
#include "base/result.hpp"
#include "base/timing_mode.hpp"
#include "bench/quality_sweep.hpp"

namespace fx {

struct FrameReport;

// --press KEY@FRAME: a window key pressed at a frame, as if typed (scripted demonstrations, the
// window tests, documentation pictures).
struct ScriptedPress {
    std::string key;  // its --press name: "space", "F2"
    int frame = 0;
    KeyPresses press;
};

// --resize WxH@FRAME: the window resized at a frame, as if the user dragged its border.
struct ScriptedResize {
    int width = 0, height = 0;
    int frame = 0;
};

struct RunOptions {
    bool help = false;
    bool listSteps = false;
    bool listParams = false;
    bool forceHeadless = false;
    std::optional<int> width, height;  // --size WxH
    std::optional<int> frames;         // --frames N (default: 3 headless, until closed in a window)
    std::optional<int> step;           // --step K, 1-based
    std::optional<int> exercise;       // --exercise N: this lesson's exercise N (app/exercise_session.hpp)
    std::filesystem::path scene;       // --scene FILE
    std::string language = "en";       // --lang en|ja: the language of the window's words
    std::filesystem::path captureDir;  // --capture DIR
    bool captureFloat = false;         // --capture-float
    std::filesystem::path reportFile;  // --report FILE
    std::filesystem::path graphFile;   // --graph FILE.dot: the last frame's graph (render/graph_dot.hpp)
    std::filesystem::path shaderDump;  // --dump-shaders DIR: every shader as compiled (gl/shader_dump.hpp)
    std::optional<double> timeStep;    // --time-step S (the lesson clock's step; default 1/60 s)
    std::uint32_t seed = 1;            // --seed N
    std::vector<std::string> params;   // --param name=value, checked once the lesson is known
    std::filesystem::path presetFile;  // --preset FILE
    TimingMode timing = TimingMode::Automatic;  // --timing gpu|fenced|off
    bool overlay = true;                        // --no-overlay; headless draws it only with --overlay
    bool overlayHeadless = false;               // --overlay
    std::vector<std::string> inspect;           // --inspect NAME: keep a texture and its producers alive
    bool bench = false;                         // --bench: sweep the quality knobs instead of running
    std::string benchKnob;                      // --knob NAME: only this knob
    int benchFrames = 5;                        // --bench-frames N: measured frames per setting
    int benchValues = 0;                        // --bench-values N: only the first N values of each knob
    std::filesystem::path benchOut;             // --bench-out DIR (default out/bench/<NN-name>)
    BenchCost benchCost = BenchCost::time;      // --cost time|traffic: the plots' cost axis
    std::vector<ScriptedPress> presses;         // --press KEY@FRAME
    std::vector<ScriptedResize> resizes;        // --resize WxH@FRAME
    bool allSteps = false;                      // --all-steps: with --capture, every step in DIR/step-K
    std::filesystem::path resourceLog;   // --resource-log FILE: memory and GL objects (app/resource_log.hpp)
    std::optional<double> pictureScale;  // --picture-scale S: pinned; nothing: automatic (a window)
    double aspect = 16.0 / 9.0;          // --aspect W:H: the picture's aspect; 0: free
    int minFrameMs = 0;                  // --min-frame-time MS: a slow renderer, imitated
    std::filesystem::path
        renderdoc;  // --renderdoc FILE.rdc: a frame in RenderDoc (app/renderdoc_session.hpp)
    std::optional<int> renderdocFrame;  // --renderdoc-frame N: that frame (1-based); default the last
    bool renderdocOpen = false;         // --renderdoc-open: the capture opens in qrenderdoc
};

// Errors name the flag and what it takes: "--size: expected WxH with sizes from 0 to 16384, got 12".
// `stepCount` is the lesson's number of steps: --step is checked against it. A flag that takes one
// value may be given once; --param and --inspect may be repeated.
Result<RunOptions> parseRunOptions(const std::vector<std::string>& args, int stepCount);

// Whether a flag takes a value ("--size" does, "--headless" does not), from the same table.
bool runFlagTakesValue(std::string_view flag);

// Every flag with its value and what it does, then the keys of a lesson window.
std::string runOptionsHelp(const std::string& program);

// --inspect names no texture of a frame: one warning per such name, naming it and the frame's
// texture names nearest to it. The names are known only once a frame's graph is built, so the
// runner asks after its first frame; `step` (0-based) is the step that frame showed.
std::vector<std::string> unknownInspectWarnings(const std::vector<std::string>& inspect,
                                                const FrameReport& report, int step);

}  // namespace fx
