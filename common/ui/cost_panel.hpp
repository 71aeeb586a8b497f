#pragma once
// The cost of the lesson's quality knobs: "measure" sweeps every knob in the running app (as
// ./fxlab bench does) and the panel draws frame time against error for each setting, with the
// reference and the setting in use marked and the settings nothing beats joined (the Pareto front).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

#include "image/plot.hpp"
#include "render/quality_sweep.hpp"

namespace fx {

// The plot of one knob's points: x = frame time in ms, y = RMSE against the reference's image.
ScatterPlot sweepPlot(const SweepResult& result, const std::string& knob);
// The knobs a sweep measured, in the order they first appear.
std::vector<std::string> sweptKnobs(const SweepResult& result);

class CostPanel {
public:
    using Measure = std::function<SweepResult()>;

    // The "measure" button asks; the sweep itself runs in runPending, which the overlay calls before
    // it starts its next ImGui frame (a sweep renders frames of its own).
    void draw(const Measure& measure);
    bool measurePending() const { return pending_; }
    void requestMeasure() { pending_ = true; }
    void runPending(const Measure& measure);

    void setResult(SweepResult result);
    const std::optional<SweepResult>& result() const { return result_; }

private:
    std::optional<SweepResult> result_;
    std::string knob_;
    bool pending_ = false;
};

// Draws a scatter plot with ImGui's primitives at the cursor (size in pixels), laid out by
// image/plot.hpp's layoutScatterPlot so the bench's picture and the panel agree.
void drawScatterPlot(const ScatterPlot& plot, ImVec2 size);

}  // namespace fx
