#pragma once
// The quality-knob sweep behind `./fxlab bench` and the overlay's cost panel: a fixed frame at the
// reference settings, then at each value of each knob (the other knobs at their references);
// the median time over several frames, the error of the final image against the reference (and of
// the lesson's own effect texture when it names one), and one plain full-screen copy timed in the
// same run so that every cost also reads as a multiple of that copy.
//
// Every knob has a reference row (the knob's reference value, or the lesson's own reference
// algorithm), even when the sweep is cut to its first values, and that row is rendered, timed and
// compared like every other row. Bench frames have FrameInfo::benchmark set: lessons leave out what
// only helps a person looking (side-by-side views, diagnostics that read textures back).
#include <filesystem>
#include <string>

#include "app/frame_renderer.hpp"
#include "render/quality_sweep.hpp"

namespace fx {

struct SweepOptions {
    std::string knob;   // empty: every knob
    int frames = 5;     // measured frames per setting (after warm-up)
    int maxValues = 0;  // 0: every value; otherwise the first N values of each knob
};

SweepResult sweepKnobs(Lesson& lesson, ParamSet& params, FrameRenderer& renderer, Context& context,
                       const SweepOptions& options, const std::string& lessonName, int step);

// out/bench/<lesson>/: bench.csv, bench.json and bench-<knob>.png (error against cost).
Status writeBenchOutputs(const SweepResult& result, const std::filesystem::path& dir);

// A plain-text table of the sweep for the terminal.
std::string describeSweep(const SweepResult& result);

}  // namespace fx
