#pragma once
// The JSON report of a run (--report FILE): who rendered, how long frames took and how that was
// measured, GL errors, every pass with why it did or did not run, and statistics of every texture
// (per channel min, max, mean, NaN and Inf counts) read back on the last frame.
#include <deque>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/capture.hpp"
#include "render/frame_report.hpp"

namespace fx {

// A parameter's value at the end of the run and where it came from ("scene", "command line"...).
struct ParamFact {
    std::string name, value, source;
    std::string label;  // the words the panel shows for it in the run's language (Param::label())
    // The values changed in other steps than the one shown (1-based step, value text), and a pin.
    std::vector<std::pair<int, std::string>> changedInSteps;
    bool pinned = false;
};

struct RunFacts {
    std::string lesson, stepTitle, contextKind, renderer, glVersion, timingMethod, timingReason, scene;
    int step = 0;  // 1-based
    Size2D size;
    // The times of the last kKeptFrames frames (a window left open for a lesson must not grow by a
    // number a frame), and how many frames ran in all.
    static constexpr std::size_t kKeptFrames = 1000;
    std::deque<double> frameCpuMs;
    std::deque<double> frameGpuMs;  // sum of the pass times the timer had for each frame
    std::uint64_t framesRun = 0;
    void addFrame(double cpuMs, double passMs);
    std::int64_t glErrors = 0, glExpectedErrors = 0, glWarnings = 0;
    // Of glExpectedErrors, those since the last step began (the panel's "this step shows on purpose").
    std::int64_t glExpectedErrorsThisStep = 0;
    std::string lastGlError;
    std::vector<std::string> shaderErrors;
    std::vector<std::pair<std::string, std::string>> lessonFacts;
    std::vector<std::pair<std::string, std::string>> shownFacts;  // label and value, as the panel shows them
    std::vector<ParamFact> params;
    std::string language = "en";            // of the words the panel showed (--lang)
    std::vector<std::string> missingWords;  // keys no words file had (base/words.hpp): a mistake
};

nlohmann::ordered_json statsJson(const std::vector<ChannelStats>& stats);

nlohmann::ordered_json buildRunReport(const RunFacts& facts, const FrameReport& lastFrame,
                                      const std::vector<CapturedTexture>& textures,
                                      const FloatImage& finalImage);

}  // namespace fx
