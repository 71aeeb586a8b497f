#pragma once
// The frames of a run: input, reload, the lesson's update and frame, the overlay on top, screenshots,
// and what the last frame leaves for the captures and the report.
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "app/frame_renderer.hpp"
#include "app/lesson_clock.hpp"
#include "app/lesson_text_files.hpp"
#include "app/resource_log.hpp"
#include "app/run_report.hpp"
#include "app/run_session.hpp"
#include "app/window_input.hpp"
#include "gl/program.hpp"
#include "ui/overlay.hpp"
#include "ui/picture_view.hpp"

namespace fx {

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
    float textScale = 1.0f;
};

class FrameLoop {
public:
    // overlay: nullptr when the run draws none.
    FrameLoop(RunSession& session, const RunPlan& plan, Context& context, FrameRenderer& renderer,
              WindowInput& input, Overlay* overlay, gl::ProgramRegistry& programs);

    // Runs plan.frames frames, or until the window closes when that is 0.
    void run();
    RunRecord& record() { return record_; }

private:
    // Starts the cost panel's sweep of the lesson's knobs (5 measured frames per setting, as the bench).
    std::function<std::unique_ptr<SweepRun>()> knobSweepStarter();
    using Clock = std::chrono::steady_clock;

    // False when the run should end (Esc, or another lesson asked for).
    bool takeKeys(Clock::time_point now, std::uint64_t index);
    void changeTextScale(float by);
    void saveUiSettings();
    FrameInfo frameInfo(std::uint64_t index, double delta, Size2D extent, const LayoutRect& place) const;
    void drawOverlay(const FrameInfo& frame, const FrameGraph& graph, const FrameReport& report, double delta,
                     Size2D window);
    void keep(RenderedFrame& rendered, bool lastFrame, bool readFinal, bool screenshot);
    void present(const LayoutRect& place, Size2D window);

    RunSession& s_;
    const RunPlan& plan_;
    Context& context_;
    FrameRenderer& renderer_;
    WindowInput& input_;
    Overlay* overlay_;
    gl::ProgramRegistry& programs_;
    bool overlayVisible_ = false;
    bool screenshotAsked_ = false;
    bool inspectChecked_ = false;  // --inspect names are checked against the first frame's graph
    LessonClock clock_;
    std::unique_ptr<PictureView> picture_;  // windows and headless overlays: the picture has its place
    CompareMode compare_ = CompareMode::Off;
    int renderedStep_ = -1;  // the step the picture now in picture_ shows
    Clock::time_point lastReloadCheck_;
    RunRecord record_;
    ResourceLog resources_;
    std::optional<LessonTextFiles> lessonText_;  // with an overlay only: the steps' text
};

}  // namespace fx
