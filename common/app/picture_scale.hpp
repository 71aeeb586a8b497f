#pragma once
// The frame budget of a lesson window: the lesson's picture is rendered at a share of its place (the
// picture scale) so that a frame stays within the budget on any renderer, and drawn into its place
// scaled up. The picture gives way first: the overlay (keys, clicks, drags) then answers on the next
// frame however slow the renderer. The scale is automatic, or pinned by --picture-scale or the key
// that cycles it (app/window_input.cpp). Headless runs, captures and the bench never scale: they
// render at exactly the size asked. GL-free, so the unit tests drive it with made-up frame times.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/size2d.hpp"

namespace fx {

// What a frame in a lesson window may cost before the picture gives way (ms): a click or a key acts
// on the next frame, which on a projector reads as an answer.
inline constexpr double kFrameBudgetMs = 200.0;
// An automatic scale never goes below this share of the place's width and height (a pinned one may).
inline constexpr double kSmallestAutomatic = 0.5;

class PictureScale {
public:
    // pinned: a fixed share (0 < s <= 1); nothing: automatic within `budgetMs`.
    explicit PictureScale(std::optional<double> pinned = std::nullopt, double budgetMs = kFrameBudgetMs);

    // The share of the place's width and height the picture renders at now.
    double scale() const { return scale_; }
    bool automatic() const { return !pinned_; }
    double budgetMs() const { return budgetMs_; }
    // The size the picture renders at inside a place of `place` (never below 1x1 unless the place is
    // empty).
    Size2D rendered(Size2D place) const;

    // The key: automatic -> 100% -> 50% -> 25% -> automatic. Returns what the scale is now, in words.
    std::string cycle();
    // A frame at the current scale took `ms` (its whole work, the overlay included): an automatic
    // scale decides the next frame's size from it. Samples right after a change are not taken
    // (a new size makes its textures and programs again). The frames at the scales tried are fitted
    // as a fixed cost plus one that grows with the pixels, and the picture gives way only where the
    // pixels pay: to the largest scale whose frame is within the budget, or else to half the place
    // (never smaller) when that at least halves the whole picture's frame; a drop that buys neither
    // is not taken (a crowd of skinned meshes, 100,000 particles on a software renderer: the time is
    // not in the pixels), and a scale tried that showed so goes back up. The notice says which.
    void frameTook(double ms);
    // The step or the picture's place changed: the next frames are measured afresh (the scale stays).
    void restart();
    // While held (the compare view: two pictures at one scale) an automatic scale does not move.
    void hold(bool on) { held_ = on; }
    // A line for the screen while the picture is not at full size ("picture at 60% of 896x504
    // (538x302): slow renderer, frame budget 200 ms (F6 pins the scale)") or the frame is over the
    // budget (what it takes, and how much of it is not in the pixels); empty otherwise.
    std::string notice(Size2D place) const;

    // The step's frame time as a fixed part and a part that grows with the picture's pixels (ms at
    // 100%), fitted to the scales measured since the step began.
    struct Cost {
        double fixed = 0, pixels = 0;
    };
    Cost cost() const;
    // The frame last measured (the median of a few), ms; 0 before the first.
    double lastFrameMs() const { return lastTypical_; }

private:
    struct Measured {
        double scale, ms;
    };
    void setScale(double scale);
    void remember(double typical);
    // The scale the cost model says pays: see frameTook.
    double chooseScale(const Cost& c) const;

    std::optional<double> pinned_;
    double budgetMs_;
    double scale_ = 1.0;
    std::vector<double> samples_;     // frames at the current scale, oldest first
    std::vector<Measured> measured_;  // the typical frame at the last few scales of this step
    bool notPixels_ = false;          // even at the smallest automatic scale the frame is over the aim
    double lastTypical_ = 0;
    bool held_ = false;
    int settle_ = 1;  // frames still to skip before sampling
};

// "40%": a scale as the screen and --help write it.
std::string percentText(double scale);

}  // namespace fx
