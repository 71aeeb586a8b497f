#pragma once
// The cost of the lesson's quality knobs: "measure" sweeps every knob in the running app (as
// ./fxlab bench does), a slice per frame with a progress bar (Esc or "cancel" stops it), and the
// panel draws cost in full-screen copies against error for each setting, with each setting's spread,
// the reference and the setting in use marked and the settings nothing beats joined (the Pareto front).
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

#include "bench/quality_sweep.hpp"
#include "image/plot.hpp"

namespace fx {

// The plot of one knob's points: x = cost in full-screen copies (median, min-max spread; frame time in
// ms when the sweep has no copy), y = RMSE against the reference's image.
ScatterPlot sweepPlot(const SweepResult& result, const std::string& knob);
// The knobs a sweep measured, in the order they first appear.
std::vector<std::string> sweptKnobs(const SweepResult& result);

class CostPanel {
public:
    using Measure = std::function<std::unique_ptr<SweepRun>()>;

    // The "measure" button asks; runPending, which the runner calls between its frames instead of
    // rendering the lesson (a sweep renders frames of its own, and none of the runner's textures may be
    // held then), starts the sweep and then measures one slice per call.
    void draw(const Measure& measure);
    // True while a sweep is asked for or under way.
    bool measurePending() const { return pending_ || running_ != nullptr; }
    void requestMeasure() { pending_ = true; }
    void runPending(const Measure& measure);
    // Stops a sweep under way; the rows measured so far are dropped and the parameters put back.
    void cancel();
    // The progress of the sweep under way (nothing when none is).
    std::optional<SweepProgress> progress() const;

    void setResult(SweepResult result);
    const std::optional<SweepResult>& result() const { return result_; }

private:
    std::optional<SweepResult> result_;
    std::string knob_;
    bool pending_ = false;
    std::unique_ptr<SweepRun> running_;
    std::string cancelled_;  // what the last cancelled sweep had reached, for the panel to say
};

// Draws a scatter plot with ImGui's primitives at the cursor (size in pixels), laid out by
// image/plot.hpp's layoutScatterPlot so the bench's picture and the panel agree.
void drawScatterPlot(const ScatterPlot& plot, ImVec2 size);

}  // namespace fx
