#pragma once
// The frames of a run: input, reload, the lesson's update and frame, the overlay on top, screenshots,
// and what the last frame leaves for the captures and the report.
//
// In a window a frame is built to answer: the lesson clock moves one fixed step a frame (so what a
// step shows never depends on the machine's speed), the picture keeps its aspect and renders at the
// share of its place that keeps the frame within the budget (app/picture_scale.hpp), long work (the
// cost panel's measure) runs a slice a frame, and what the teacher did is confirmed on screen.
#include <chrono>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "app/exercise_session.hpp"
#include "app/frame_renderer.hpp"
#include "app/lesson_clock.hpp"
#include "app/lesson_text_files.hpp"
#include "app/picture_scale.hpp"
#include "app/resource_log.hpp"
#include "app/run_report.hpp"
#include "app/run_session.hpp"
#include "app/window_input.hpp"
#include "gl/program.hpp"
#include "ui/overlay.hpp"
#include "ui/picture_view.hpp"

namespace fx {

// Where the last frame's picture was and at what scale (the report's "picture").
struct PictureRecord {
    Size2D place, rendered;
    double scale = 1.0;
    bool automatic = false;
};

// What the run has seen, for the captures and the report.
struct RunRecord {
    RunFacts facts;
    FrameReport lastReport;
    std::vector<CapturedTexture> lastTextures;
    ByteImage lastFinalBytes;
    FloatImage lastFinal;
    FrameInfo lastFrame;  // the last frame the lesson built (its facts go in the report)
    // With the picture in its own place (a window, or the overlay headless): the lesson's picture
    // alone, and where it and the panels were in the window.
    ByteImage lastPicture;
    std::optional<PanelLayout> lastLayout;
    std::optional<PictureRecord> lastPictureScale;
    float textScale = 1.0f;
    // The lesson clock at the end of the run (the report's "clock").
    double clockSeconds = 0;
    std::uint64_t clockSteps = 0;
    bool clockPaused = false;
    // The run's count of GL errors shown on purpose when the step on screen began.
    std::int64_t expectedErrorsBeforeStep = 0;
};

class FrameLoop {
public:
    // overlay: nullptr when the run draws none.
    FrameLoop(RunSession& session, const RunPlan& plan, Context& context, FrameRenderer& renderer,
              WindowInput& input, Overlay* overlay, gl::ProgramRegistry& programs);
    // Frees the exercise's pictures while the context is still current.
    ~FrameLoop();
    FrameLoop(const FrameLoop&) = delete;
    FrameLoop& operator=(const FrameLoop&) = delete;

    // Runs plan.frames frames, or until the window closes when that is 0.
    void run();
    RunRecord& record() { return record_; }

private:
    using Clock = std::chrono::steady_clock;

    // Where this frame's picture goes and what size it renders at.
    struct Placement {
        Size2D window;
        std::optional<PanelLayout> layout;  // with the overlay: where the panels are
        LayoutRect place;                   // the picture's place in the window (its aspect kept)
        Size2D extent;                      // what the lesson renders at (the place, scaled)
    };
    Placement placeFrame(bool drawOverlay) const;

    // Starts the cost panel's sweep of the lesson's knobs at the picture's size (5 measured frames
    // per setting, as the bench), measured a slice per frame.
    std::function<std::unique_ptr<SweepRun>()> knobSweepStarter(Size2D size);
    // One slice of the cost panel's sweep instead of the lesson's frame: the picture holds still and
    // the overlay draws over it with the last frame's report.
    void measureSlice(const Placement& at, std::uint64_t index);

    // False when the run should end (Esc, or another lesson asked for).
    bool takeKeys(Clock::time_point now, std::uint64_t index);
    // After the keys and the overlay may have changed the step: the step's own parameters and counts.
    void enterStep();
    void setCompare(CompareMode mode);
    // On a probe exercise's step F3 shows the student's result, the reference's and their difference
    // (app/exercise_session.hpp) instead of comparing steps.
    bool onExerciseStep() const;
    void setExerciseView(ExerciseView view);
    void drawExerciseView(GLuint window, Size2D windowSize, const LayoutRect& place);
    // The step before, drawn again at this moment of the lesson clock into the compare view's kept
    // picture, so that F3 compares the two steps at one moment (not the step before as it was when left).
    void renderPreviousStepNow(const Placement& at, std::uint64_t index);
    void changeTextScale(float by);
    void saveUiSettings();
    // A short notice at the top of the lesson window (F12's file, the first or last lesson, a reload),
    // also kept as the status line and logged.
    void notify(std::string text);
    FrameInfo frameInfo(std::uint64_t index, double delta, const Placement& at) const;
    void drawOverlay(const FrameInfo& frame, const FrameGraph* graph, const FrameReport& report, double delta,
                     const Placement& at);
    void keep(RenderedFrame& rendered, bool lastFrame, bool readFinal, bool screenshot);
    void present(const LayoutRect& place, Size2D window);
    // After a window's frame: the picture scale learns what it cost, and a frame faster than the
    // lesson clock's step (or --min-frame-time) waits the rest.
    void endWindowFrame(Clock::time_point frameStart, double frameMs, double delta);
    // "lesson clock at 0.12x real time ..." while it runs slower than the wall clock; else empty.
    std::string clockRateNotice() const;

    RunSession& s_;
    const RunPlan& plan_;
    Context& context_;
    FrameRenderer& renderer_;
    WindowInput& input_;
    Overlay* overlay_;
    gl::ProgramRegistry& programs_;
    bool overlayVisible_ = false;
    bool screenshotAsked_ = false;
    KeyPresses heldBack_;          // keys that wait a frame for the overlay to see a click, Enter or Esc
    bool inspectChecked_ = false;  // --inspect names are checked against the first frame's graph
    LessonClock clock_;
    PictureScale pictureScale_;
    std::unique_ptr<PictureView> picture_;  // windows and headless overlays: the picture has its place
    CompareMode compare_ = CompareMode::Off;
    ExerciseView exerciseView_ = ExerciseView::Off;
    ExerciseView loggedExerciseView_ = ExerciseView::Off;  // the view whose place the log has said
    int renderedStep_ = -1;                                // the step the picture now in picture_ shows
    // The step whose parameters and counts are in force: a step change moves the parameters to the new
    // step's own (ParamSet::changeStep) and starts its count of the GL errors it shows on purpose.
    int paramStep_ = -1;
    double previousSeconds_ = -1.0;  // the lesson clock's time of the kept picture of the step before
    bool refreshPrevious_ = false;   // draw the step before again, at this moment, before this frame
    Size2D lastPlace_;               // the picture's place last frame (the scale restarts on a change)
    std::deque<std::pair<double, double>> clockRate_;  // the last frames' (wall, lesson) seconds
    Clock::time_point lastReloadCheck_;
    std::string notice_;
    Clock::time_point noticeUntil_;
    RunRecord record_;
    ResourceLog resources_;
    std::optional<LessonTextFiles> lessonText_;  // with an overlay only: the steps' text
};

}  // namespace fx
