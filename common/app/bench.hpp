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
#include <functional>
#include <memory>
#include <string>

#include "app/frame_renderer.hpp"
#include "bench/quality_sweep.hpp"

namespace fx {

struct SweepOptions {
    std::string knob;   // empty: every knob
    int frames = 5;     // measured frames per setting (after warm-up), each with a copy before it
    int maxValues = 0;  // 0: every value; otherwise the first N values of each knob
    std::function<void(const SweepProgress&)> progress;  // called before each row and at the end
    Size2D size{};  // the frames' size; empty: the context's framebuffer (the bench's --size)
};

// A sweep measured a slice at a time (one frame of a setting, with its copy), so an interactive app
// draws its own frames (and a progress bar) between slices and can stop early. The parameters are put
// back after every slice: the overlay drawn between slices shows the settings the user chose.
class KnobSweep final : public SweepRun {
public:
    KnobSweep(Lesson& lesson, ParamSet& params, FrameRenderer& renderer, Context& context,
              SweepOptions options, std::string lessonName, int step);
    ~KnobSweep() override;
    KnobSweep(const KnobSweep&) = delete;
    KnobSweep& operator=(const KnobSweep&) = delete;

    bool done() const override;
    // Renders the next frame of the setting under way (the first setting is the reference image).
    void next() override;
    SweepProgress progress() const override;
    const SweepResult& result() const override { return result_; }

private:
    struct Row;
    struct Impl;
    std::unique_ptr<Impl> impl_;
    SweepResult result_;
};

// The whole sweep at once (./fxlab bench, tests).
SweepResult sweepKnobs(Lesson& lesson, ParamSet& params, FrameRenderer& renderer, Context& context,
                       const SweepOptions& options, const std::string& lessonName, int step);

// out/bench/<lesson>/: bench.csv, bench.json and bench-<knob>.png (error against cost).
Status writeBenchOutputs(const SweepResult& result, const std::filesystem::path& dir,
                         BenchCost cost = BenchCost::time);

// A plain-text table of the sweep for the terminal, then where the time goes: every pass of the
// setting in use (or the first row) in copies.
std::string describeSweep(const SweepResult& result);

// The line ./fxlab bench prints for a lesson with nothing to sweep.
std::string noKnobsMessage(const std::string& lessonName);

}  // namespace fx
