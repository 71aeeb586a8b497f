#pragma once
// The lesson's clock, which a teacher can hold still to talk about one frame: space pauses and
// resumes, "." moves one fixed step forward (and pauses). While paused the lesson and its simulations
// see a delta of 0 and the same time every frame, so an animated scene stands still; frames still
// render (the overlay, the inspector and the compare view stay live).
namespace fx {

class LessonClock {
public:
    // fixedStep: what one "." adds (the run's --time-step, 1/60 s by default).
    explicit LessonClock(double fixedStep) : fixedStep_(fixedStep) {}

    void togglePause() { paused_ = !paused_; }
    void stepOnce() {
        paused_ = true;
        ++pendingSteps_;
    }
    bool paused() const { return paused_; }

    // The time this frame adds, given the time that passed since the last one.
    double advance(double elapsed) {
        double delta = elapsed;
        if (paused_) {
            delta = pendingSteps_ > 0 ? fixedStep_ : 0.0;
            if (pendingSteps_ > 0) --pendingSteps_;
        }
        seconds_ += delta;
        return delta;
    }
    double seconds() const { return seconds_; }

private:
    double fixedStep_;
    double seconds_ = 0;
    bool paused_ = false;
    int pendingSteps_ = 0;
};

}  // namespace fx
