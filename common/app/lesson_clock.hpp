#pragma once
// The lesson's clock: every frame a lesson builds moves it one fixed step (--time-step, 1/60 s by
// default), in a window as headless, so what a step shows depends on the lesson clock and never on
// how fast the machine renders: a frame that takes 300 ms on a software renderer is still one 1/60 s
// step of the fire's simulation, exactly as in a headless capture. (A step that wants a long frame
// injects it itself, as lesson 07's hitch does.) On a slow machine the lesson's time then runs slower
// than the wall clock; the runner says so on screen (FrameLoop).
//
// A teacher can hold it still to talk about one frame: space pauses and resumes, "." moves one fixed
// step forward (and pauses). The compare view holds it too, so that both steps are seen at the same
// moment. While stopped the lesson and its simulations see a delta of 0 and the same time every frame;
// frames still render (the overlay, the inspector and the compare view stay live).
#include <cstdint>

namespace fx {

class LessonClock {
public:
    explicit LessonClock(double fixedStep) : fixedStep_(fixedStep) {}

    void togglePause() { paused_ = !paused_; }
    void stepOnce() {
        paused_ = true;
        ++pendingSteps_;
    }
    bool paused() const { return paused_; }
    // Held by the compare view (apart from the teacher's pause, which it leaves as it was). While held
    // even "." does not move the clock: the kept picture of the other step would no longer match.
    void hold(bool on) { held_ = on; }
    bool held() const { return held_; }

    // One frame: the time it adds (one fixed step, or 0 while stopped).
    double advance() {
        double delta = fixedStep_;
        if (held_) {
            delta = 0.0;
        } else if (paused_) {
            delta = pendingSteps_ > 0 ? fixedStep_ : 0.0;
            if (pendingSteps_ > 0) --pendingSteps_;
        }
        // Summed step by step (not steps * fixedStep), so the times are the ones every run has had.
        seconds_ += delta;
        if (delta > 0) ++steps_;
        return delta;
    }
    double seconds() const { return seconds_; }
    // Fixed steps taken so far (this frame's included): a frame's number on the lesson's own clock.
    std::uint64_t steps() const { return steps_; }
    double fixedStep() const { return fixedStep_; }

private:
    double fixedStep_;
    double seconds_ = 0;
    std::uint64_t steps_ = 0;
    bool paused_ = false;
    bool held_ = false;
    int pendingSteps_ = 0;
};

}  // namespace fx
