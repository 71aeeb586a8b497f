#include "app/frame_loop.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <thread>

#include "app/bench.hpp"
#include "app/capture.hpp"
#include "app/exercise_session.hpp"
#include "app/facts_panel.hpp"
#include "app/lesson_listing.hpp"
#include "app/lesson_switch.hpp"
#include "app/renderdoc_session.hpp"
#include "app/run_options.hpp"
#include "base/fact_references.hpp"
#include "base/file_io.hpp"
#include "base/log.hpp"
#include "base/words.hpp"
#include "gl/debug_output.hpp"
#include "image/png_file.hpp"

namespace fx {

namespace fs = std::filesystem;

namespace {

std::string secondsText(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", seconds);
    return text;
}

// The clock's step as people write it: "1/60 s", "0.5 s".
std::string stepText(double seconds) {
    const double perSecond = 1.0 / seconds;
    char text[32];
    if (perSecond > 1.5 && std::abs(perSecond - std::round(perSecond)) < 1e-6)
        std::snprintf(text, sizeof text, "1/%.0f s", perSecond);
    else
        std::snprintf(text, sizeof text, "%.3g s", seconds);
    return text;
}

// How long a notice stays at the top of the lesson window.
constexpr std::chrono::seconds kNoticeTime{5};
// The lesson clock's pace against the wall clock is judged over about this long.
constexpr double kClockRateWindowS = 2.0;

}  // namespace

FrameLoop::FrameLoop(RunSession& session, const RunPlan& plan, Context& context, FrameRenderer& renderer,
                     WindowInput& input, Overlay* overlay, gl::ProgramRegistry& programs)
    : s_(session),
      plan_(plan),
      context_(context),
      renderer_(renderer),
      input_(input),
      overlay_(overlay),
      programs_(programs),
      overlayVisible_(plan.headless ? session.options.overlayHeadless : session.options.overlay),
      clock_(session.options.timeStep.value_or(1.0 / 60.0)),
      // Headless the picture is never scaled by itself: a capture is the size asked (or the scale pinned).
      pictureScale_(plan.headless ? session.options.pictureScale.value_or(1.0)
                                  : session.options.pictureScale),
      resources_(session.options.resourceLog) {
    RunFacts& facts = record_.facts;
    facts.lesson = s_.exe;
    facts.contextKind = context.kind();
    facts.renderer = context.renderer();
    facts.glVersion = context.version();
    facts.timingMethod = std::string(toString(renderer.timer().method()));
    facts.timingReason = renderer.timer().reason();
    facts.scene = s_.scene.file.string();
    // A run whose every frame is minimised still reports the lesson's facts about its scene.
    record_.lastFrame.world = renderer.world(0.0);
    // The steps' text from lesson.md (or lesson.ja.md), for the overlay; read again when saved.
    if (overlay_) {
        lessonText_.emplace(lessonSourceFolder(s_.lesson->info()), s_.lesson->steps(), s_.options.language);
        (void)lessonText_->reloadIfChanged();
        overlay_->setTextScale(s_.ui.textScale);
        overlay_->setShares(s_.ui.shares);
    }
    // In a window the picture always has its own place (and the compare view); headless only with the
    // overlay, so captures without it are the lesson's frame exactly as before.
    if (!plan.headless || overlay_) picture_ = std::make_unique<PictureView>();
}

FrameLoop::~FrameLoop() {
    if (s_.exercise) s_.exercise->releasePictures();
}

void FrameLoop::run() {
    const std::uint64_t frames = std::uint64_t(plan_.frames);
    lastReloadCheck_ = Clock::now();
    gl::resetDebugCounters();
    paramStep_ = s_.step;

    for (std::uint64_t index = 0; frames == 0 || index < frames; ++index) {
        resources_.atFrame(index, s_.step, context_.framebufferSize());
        context_.pollEvents();
        if (context_.shouldClose()) break;
        if (!plan_.headless && context_.hidden()) {
            // Minimised or unmapped: nothing is seen, so nothing is drawn and the lesson clock stands
            // still; sleep until the window system has news (a quarter second at most, so the shader
            // watch still runs).
            context_.waitEvents(0.25);
            record_.facts.addFrame(0, 0);
            continue;
        }
        const Clock::time_point frameStart = Clock::now();
        if (!takeKeys(frameStart, index)) break;
        enterStep();
        const bool drawOverlay = overlay_ && overlayVisible_;
        const Placement at = placeFrame(drawOverlay);
        if (drawOverlay && overlay_->costPanel().measurePending() && !at.extent.empty()) {
            measureSlice(at, index);
            continue;
        }
        if (s_.renderdoc) s_.renderdoc->frameStarts(index, frames != 0 && index + 1 == frames);
        // --exercise: a saved student's file is checked again before the frame that shows it.
        if (s_.exercise) (void)s_.exercise->recheckIfChanged();
        const double delta = clock_.advance();
        FrameInfo frame = frameInfo(index, delta, at);
        // The step before at this picture's size: the place or the scale changed while comparing.
        if (compare_ != CompareMode::Off && picture_ && picture_->previousStep() &&
            picture_->previousSize() != at.extent)
            refreshPrevious_ = true;
        if (refreshPrevious_ && !at.extent.empty()) renderPreviousStepNow(at, index);
        if (SceneWork* work = renderer_.sceneWork()) work->update(frame.seconds, frame.deltaSeconds);
        s_.lesson->update(frame);
        if (at.extent.empty()) {
            // Minimised (or --size 0x0): nothing to draw into, and aspect = w/0 must not happen.
            if (!plan_.headless) context_.waitEvents(0.25);
            record_.facts.addFrame(0, 0);
            continue;
        }
        const bool lastFrame = frames != 0 && index + 1 == frames;
        const bool screenshot = std::exchange(screenshotAsked_, false);
        FrameRequest request;
        request.inspect = s_.options.inspect;
        // What the inspector shows stays alive, with the passes that make it.
        if (drawOverlay) {
            for (auto& name : overlay_->wantedTextures()) request.inspect.push_back(name);
        }
        request.readTextures = lastFrame;
        request.readFinal = lastFrame || screenshot;
        if (picture_) {
            // The picture of the step before is kept for the compare view before this step draws.
            if (renderedStep_ >= 0 && renderedStep_ != s_.step) {
                picture_->keepAsPrevious(renderedStep_);
                previousSeconds_ = record_.lastFrame.seconds;
                pictureScale_.restart();  // another step costs differently
            }
            renderedStep_ = s_.step;
            request.target = picture_->target(at.extent);
        }
        RenderedFrame rendered = renderer_.render(*s_.lesson, frame, request,
                                                  [&](const FrameGraph& graph, const FrameReport& report) {
                                                      if (picture_) present(at.place, at.window);
                                                      if (drawOverlay)
                                                          this->drawOverlay(frame, &graph, report, delta, at);
                                                  });
        if (!inspectChecked_) {
            inspectChecked_ = true;  // the first frame's graph knows the texture names --inspect can use
            for (const auto& warning : unknownInspectWarnings(s_.options.inspect, rendered.report, s_.step))
                log::warning(warning);
        }
        record_.lastFrame = frame;
        if (lastFrame && picture_) {
            record_.lastPicture = picture_->read();
            record_.lastLayout = at.layout;
            record_.lastPictureScale = PictureRecord{{int(at.place.width), int(at.place.height)},
                                                     at.extent,
                                                     pictureScale_.scale(),
                                                     pictureScale_.automatic()};
            if (overlay_) record_.textScale = overlay_->textScale();
        }
        keep(rendered, lastFrame, request.readFinal, screenshot);
        context_.present();
        if (s_.renderdoc)
            if (auto captured = s_.renderdoc->frameEnded()) notify(*captured);
        gl::drainErrorFlags();
        const double frameMs = std::chrono::duration<double, std::milli>(Clock::now() - frameStart).count();
        record_.facts.addFrame(frameMs, rendered.passMs);
        if (!plan_.headless) endWindowFrame(frameStart, frameMs, delta);
    }
    // The facts of the last frame read the last frame's report.
    record_.lastFrame.previousFrame = &record_.lastReport;
    record_.clockSeconds = clock_.seconds();
    record_.clockSteps = clock_.steps();
    record_.clockPaused = clock_.paused();
    s_.windowSize = context_.framebufferSize();
    saveUiSettings();
    if (Status written = resources_.write(); !written) log::error(written.error());
}

FrameLoop::Placement FrameLoop::placeFrame(bool drawOverlay) const {
    Placement at;
    at.window = context_.framebufferSize();
    // The picture's place: beside the panels when they show, else the whole window.
    at.place = {0, 0, float(at.window.width), float(at.window.height)};
    if (drawOverlay && picture_ && !at.window.empty()) {
        at.layout = overlay_->layout(at.window.width, at.window.height);
        at.place = at.layout->picture;
    }
    if (at.window.empty()) return at;
    if (!picture_) {
        at.extent = at.window;  // headless without the overlay: exactly the size asked
        return at;
    }
    // The aspect the lesson's text assumes, letterboxed in the place; then the frame budget's share.
    at.place = keepAspect(at.place, s_.options.aspect);
    if (at.layout) at.layout->picture = at.place;
    at.extent = pictureScale_.rendered({int(at.place.width), int(at.place.height)});
    return at;
}

void FrameLoop::present(const LayoutRect& place, Size2D window) {
    // Around the picture (the bars its aspect leaves, and where no panel is during a resize): a dark ground.
    gl::DebugGroup group("present picture");
    const GLuint target = context_.presentFramebuffer();
    const float ground[4] = {0.08f, 0.08f, 0.09f, 1.0f};
    glClearNamedFramebufferfv(target, GL_COLOR, 0, ground);
    if (exerciseView_ != ExerciseView::Off && onExerciseStep())
        drawExerciseView(target, window, place);
    else
        picture_->present(target, window.height, place, compare_);
}

bool FrameLoop::onExerciseStep() const {
    return s_.exercise && s_.exercise->hasViews() && s_.step == s_.exercise->step();
}

void FrameLoop::setExerciseView(ExerciseView view) {
    exerciseView_ = view;
    loggedExerciseView_ = ExerciseView::Off;
    if (view == ExerciseView::Off) {
        notify(say("notice.exerciseViewOff",
                   {{"verdict", say(s_.exercise->verdict().passed ? "check.pass" : "check.fail")}}));
        return;
    }
    // While it is on the lesson window says what is shown (FrameLoop::drawOverlay).
    s_.status = s_.exercise->describeView(view);
    log::info(s_.status);
}

void FrameLoop::drawExerciseView(GLuint window, Size2D windowSize, const LayoutRect& place) {
    const ExerciseSession& e = *s_.exercise;
    const bool difference = exerciseView_ == ExerciseView::Difference;
    const gl::Texture& first =
        exerciseView_ == ExerciseView::Reference ? e.referencePicture() : e.studentPicture();
    const LayoutRect at = picture_->drawPair(window, windowSize.height, place,
                                             difference ? PairView::Difference : PairView::First, first,
                                             e.referencePicture(), e.display());
    // Where it went, once per view: the window test reads the pixels there.
    if (std::exchange(loggedExerciseView_, exerciseView_) != exerciseView_)
        log::info("exercise view ", int(exerciseView_), " drawn at ", int(at.x), ",", int(at.y), " ",
                  int(at.width), "x", int(at.height), " in the ", windowSize.width, "x", windowSize.height,
                  " window");
}

std::function<std::unique_ptr<SweepRun>()> FrameLoop::knobSweepStarter(Size2D size) {
    return [this, size]() -> std::unique_ptr<SweepRun> {
        SweepOptions options;
        options.size = size;  // the picture's size: the cost of what the class sees
        return std::make_unique<KnobSweep>(*s_.lesson, s_.params, renderer_, context_, options, s_.exe,
                                           s_.step);
    };
}

void FrameLoop::measureSlice(const Placement& at, std::uint64_t index) {
    const Clock::time_point start = Clock::now();
    // The sweep renders its own frames into the window's framebuffer, outside any frame of the loop
    // (so no texture the overlay holds is released under it); then the picture is put back over them.
    overlay_->costPanel().runPending(knobSweepStarter(at.extent));
    if (picture_) present(at.place, at.window);
    FrameInfo frame = record_.lastFrame;
    frame.index = index;
    frame.previousFrame = &record_.lastReport;
    drawOverlay(frame, nullptr, record_.lastReport, 0.0, at);
    context_.present();
    gl::drainErrorFlags();
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    record_.facts.addFrame(ms, 0);
    if (!overlay_->costPanel().measurePending()) notify(say("notice.measured"));
}

void FrameLoop::setCompare(CompareMode mode) {
    if (!picture_) {
        notify(say("notice.compareNeedsWindow"));
        return;
    }
    const bool wasOn = compare_ != CompareMode::Off;
    compare_ = mode;
    const bool on = compare_ != CompareMode::Off;
    // Both steps at one moment: the clock holds while comparing, and the step before is drawn again at
    // this moment when the view opens.
    clock_.hold(on);
    // And at one scale: an automatic scale holds while comparing (F6 still changes it, and then the step
    // before is drawn again at the new size).
    pictureScale_.hold(on);
    if (on && !wasOn) refreshPrevious_ = true;
    // While it is on the lesson window says what is compared (FrameLoop::drawOverlay); off, a notice.
    if (on) {
        s_.status = cat("compare: ", describeCompareMode(compare_));
        log::info(s_.status);
    } else {
        notify(say("notice.compareOff"));
    }
}

void FrameLoop::renderPreviousStepNow(const Placement& at, std::uint64_t index) {
    refreshPrevious_ = false;
    const std::optional<int> previous = picture_->previousStep();
    if (!previous || *previous == s_.step) return;
    if (previousSeconds_ == clock_.seconds() && picture_->previousSize() == at.extent) return;
    const int current = std::exchange(s_.step, *previous);
    s_.params.changeStep(current, *previous);  // the step before with its own values
    FrameInfo frame = frameInfo(index, 0.0, at);
    if (SceneWork* work = renderer_.sceneWork()) work->update(frame.seconds, 0.0);
    s_.lesson->update(frame);
    FrameRequest request;
    request.target = picture_->target(at.extent);
    (void)renderer_.render(*s_.lesson, frame, request);
    picture_->keepAsPrevious(*previous);
    previousSeconds_ = frame.seconds;
    s_.params.changeStep(*previous, current);
    s_.step = current;
}

void FrameLoop::enterStep() {
    if (s_.step == paramStep_) return;
    s_.params.changeStep(paramStep_, s_.step);
    paramStep_ = s_.step;
    record_.expectedErrorsBeforeStep = gl::debugCounters().expectedErrors;
}

bool FrameLoop::takeKeys(Clock::time_point now, std::uint64_t index) {
    int stepCount = int(s_.lesson->steps().size());
    KeyPresses keys = input_.takeKeyPresses();
    keys |= std::exchange(heldBack_, KeyPresses{});
    if (overlay_) {
        // A text field being edited owns the keys it uses (the arrows move its cursor, "." is a decimal
        // point, Enter and Esc leave it); the F keys and Page Up/Down stay the app's. The overlay learns
        // of a click, an Enter or an Esc only when it next draws, so keys pressed in the same moment wait
        // one frame: the click may open a field, the Enter close one, and then it is clear whose they are.
        const bool editing = overlay_->wantsTextInput();
        const bool undecided = keys.clicked || (editing && keys.enterOrEscape);
        KeyPresses fieldKeys = takeTextFieldKeys(keys);
        if (undecided)
            heldBack_ = fieldKeys;
        else if (!editing)
            keys |= fieldKeys;
    }
    // --press KEY@FRAME: the same presses, at the frame asked for.
    for (const ScriptedPress& p : s_.options.presses) {
        if (std::uint64_t(p.frame) == index) keys |= p.press;
    }
    for (const ScriptedResize& r : s_.options.resizes) {
        if (std::uint64_t(r.frame) == index) context_.resize({r.width, r.height});
    }
    if (keys.next) s_.step = std::min(s_.step + 1, stepCount - 1);
    if (keys.previous) s_.step = std::max(s_.step - 1, 0);
    if (keys.toggleOverlay) overlayVisible_ = !overlayVisible_;
    if (keys.pause) clock_.togglePause();
    if (keys.advanceFrame) {
        if (clock_.held())
            notify(say("notice.clockHolds", {{"key", windowKeyName(&KeyPresses::compare)}}));
        else
            clock_.stepOnce();
    }
    if (keys.textBigger) changeTextScale(kTextScaleStep);
    if (keys.textSmaller) changeTextScale(-kTextScaleStep);
    if (keys.resetLayout && overlay_) {
        overlay_->resetLayout();
        notify(say("notice.layoutReset"));
        saveUiSettings();
    }
    if (keys.compare) {
        if (picture_ && onExerciseStep())
            setExerciseView(nextExerciseView(exerciseView_));
        else
            setCompare(nextCompareMode(compare_));
    }
    if (keys.pictureScale) notify(pictureScale_.cycle());
    if (keys.findSpecial && overlay_) {
        overlay_->inspector().setOpen(true);
        overlay_->inspector().findNextSpecial();
    }
    if (overlay_) {
        // Esc stops the cost panel's sweep rather than the app while one runs.
        if (keys.quit && overlay_->costPanel().measurePending()) {
            keys.quit = false;
            overlay_->costPanel().cancel();
            notify(say("notice.measureCancelledEsc"));
        }
        if (keys.measure) {
            if (overlay_->costPanel().measurePending()) {
                overlay_->costPanel().cancel();
                notify(say("notice.measureCancelled"));
            } else {
                overlay_->showFramePanel(true, true);
                overlay_->costPanel().requestMeasure();
                notify(say("notice.measuring"));
            }
        }
    }
    screenshotAsked_ = keys.screenshot;
    if (keys.renderdoc) {
        if (s_.renderdoc)
            s_.renderdoc->captureNextFrame();
        else
            notify(
                "RenderDoc: start the lesson with --renderdoc FILE.rdc to capture frames (docs/debugging.md)");
    }
    if (!plan_.headless && now - lastReloadCheck_ > std::chrono::milliseconds(500)) {
        lastReloadCheck_ = now;
        if (int reloaded = programs_.reloadChanged(); reloaded > 0) {
            const std::size_t failed = programs_.errors().size();
            // One list of values and a choice of key (a choice of two braced lists trips GCC 12's
            // -Wmaybe-uninitialized).
            const WordArgs counts{{"count", cat(failed == 0 ? std::size_t(reloaded) : failed)}};
            notify(say(failed == 0 ? "notice.savedRebuilt" : "notice.savedFailed", counts));
        }
        if (lessonText_) (void)lessonText_->reloadIfChanged();
    }
    if (keys.reload) {
        const int reloaded = programs_.reloadAll();
        const std::size_t failed = programs_.errors().size();
        const WordArgs counts{{"count", cat(reloaded)}, {"failed", cat(failed)}};
        notify(say(failed == 0 ? "notice.reloaded" : "notice.reloadedFailed", counts));
    }
    if (keys.nextLesson || keys.previousLesson) {
        const int direction = keys.nextLesson ? 1 : -1;
        if (neighbourLesson(s_.exe, direction)) {
            s_.switchLesson = direction;
            return false;
        }
        notify(say(direction > 0 ? "notice.lastLesson" : "notice.firstLesson"));
    }
    return !keys.quit;
}

void FrameLoop::notify(std::string text) {
    log::info(text);
    s_.status = text;
    notice_ = std::move(text);
    noticeUntil_ = Clock::now() + kNoticeTime;
}

void FrameLoop::changeTextScale(float by) {
    if (!overlay_) return;
    const float scale = clampTextScale(overlay_->textScale() + by);
    overlay_->setTextScale(scale);
    notify(say("notice.textScale", {{"scale", cat(scale)}}));
    saveUiSettings();
}

void FrameLoop::saveUiSettings() {
    // Only a window's settings are the teacher's: headless runs (tests, captures) leave the file alone.
    if (plan_.headless) return;
    if (overlay_) {
        s_.ui.textScale = overlay_->textScale();
        s_.ui.shares = overlay_->shares();
    }
    Size2D window = context_.framebufferSize();
    if (!window.empty()) s_.ui.windowSize = window;
    if (auto saved = fx::saveUiSettings(uiSettingsPath(), s_.ui); !saved) log::warning(saved.error());
}

void FrameLoop::endWindowFrame(Clock::time_point frameStart, double frameMs, double delta) {
    // The scale learns from the frame's own work, never from the wait below.
    if (!overlay_ || !overlay_->costPanel().measurePending()) pictureScale_.frameTook(frameMs);
    // Never faster than the lesson clock: a fast renderer shows the lesson at the wall clock's pace.
    const double least = std::max(clock_.fixedStep(), s_.options.minFrameMs / 1000.0);
    std::this_thread::sleep_until(
        frameStart + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(least)));
    const double wall = std::chrono::duration<double>(Clock::now() - frameStart).count();
    clockRate_.emplace_back(wall, delta);
    double total = 0;
    for (const auto& [w, d] : clockRate_) total += w;
    while (clockRate_.size() > 2 && total - clockRate_.front().first > kClockRateWindowS) {
        total -= clockRate_.front().first;
        clockRate_.pop_front();
    }
}

std::string FrameLoop::clockRateNotice() const {
    if (clock_.paused() || clock_.held() || clockRate_.size() < 3) return {};
    double wall = 0, lesson = 0;
    for (const auto& [w, d] : clockRate_) {
        wall += w;
        lesson += d;
    }
    const double rate = wall > 0 ? lesson / wall : 1.0;
    if (rate > 0.9) return {};
    char text[16];
    std::snprintf(text, sizeof text, "%.2g", rate);
    return cat("lesson clock at ", text, "x the wall clock (one ", stepText(clock_.fixedStep()),
               " step a frame, as headless)");
}

FrameInfo FrameLoop::frameInfo(std::uint64_t index, double delta, const Placement& at) const {
    FrameInfo frame;
    frame.index = index;
    frame.deltaSeconds = delta;
    frame.seconds = clock_.seconds();
    frame.world = renderer_.world(frame.seconds);
    frame.clockSteps = clock_.steps();
    frame.frameBudgetMs = plan_.headless ? 0.0 : pictureScale_.budgetMs();
    frame.size = at.extent;
    frame.step = s_.step;
    frame.seed = s_.options.seed;
    frame.headless = plan_.headless;
    frame.previousFrame = index > 0 ? &record_.lastReport : nullptr;
    frame.pointer = input_.pointer(at.window, int(at.place.x), int(at.place.y),
                                   {int(at.place.width), int(at.place.height)}, at.extent,
                                   overlay_ && overlayVisible_ && overlay_->wantsMouse());
    return frame;
}

void FrameLoop::drawOverlay(const FrameInfo& frame, const FrameGraph* graph, const FrameReport& report,
                            double delta, const Placement& at) {
    glBindFramebuffer(GL_FRAMEBUFFER, context_.presentFramebuffer());
    glViewport(0, 0, at.window.width, at.window.height);
    Lesson& lesson = *s_.lesson;
    OverlayModel model;
    if (lessonText_ && lessonText_->language() != words().language()) {
        // The ja button: the panel's words follow the steps' text.
        auto loaded = Words::load(lessonSourceFolder(lesson.info()), lessonText_->language());
        if (loaded)
            useWords(std::move(*loaded));
        else
            notify(loaded.error());
    }
    model.title = say("lesson.title", {{"number", cat(lesson.info().number)},
                                       {"title", words().textOr("lesson.name", lesson.info().title)}});
    model.words = words().allTexts();
    if (lessonText_) {
        model.steps = lessonText_->steps();
        model.pages = lessonText_->pages();
        model.textError = lessonText_->error();
        model.textRevision = lessonText_->revision();
        model.language = lessonText_->language();
        model.languages = lessonText_->available();
        model.setLanguage = [this](const std::string& language) { (void)lessonText_->setLanguage(language); };
    }
    if (s_.exercise) s_.exercise->annotate(model.steps, model.textRevision);
    // The lesson's facts of this frame: the panel lists them, and the step's text quotes them by
    // reference ({fact:NAME}), so its numbers are this frame's (base/fact_references.hpp).
    Facts facts;
    lesson.facts(facts, frame);
    if (s_.step >= 0 && std::size_t(s_.step) < model.steps.size()) {
        std::string& text = model.steps[std::size_t(s_.step)].text;
        text = resolveFactReferences(text, [&facts](const std::string& name) -> std::optional<std::string> {
            const std::string* value = facts.find(name);
            return value ? std::optional(*value) : std::nullopt;
        });
    }
    model.step = &s_.step;
    model.params = &s_.params;
    model.frame = &report;
    model.graph = graph;
    model.cameraNear = s_.scene.camera.near;
    model.cameraFar = s_.scene.camera.far;
    model.timing = cat(toString(renderer_.timer().method()));
    model.renderer = cat(context_.renderer(), " (", context_.kind(), ")");
    model.frameMs = record_.facts.frameCpuMs.empty() ? 0 : record_.facts.frameCpuMs.back();
    model.glErrors = gl::debugCounters().errors;
    model.glExpectedErrors = gl::debugCounters().expectedErrors - record_.expectedErrorsBeforeStep;
    model.shaderErrors = programs_.errors();
    model.status = s_.status;
    if (Clock::now() < noticeUntil_) model.notice = notice_;
    model.lessonPanel = [&] {
        drawFacts(facts, frame.size);
        lesson.drawPanel(frame);
    };
    fs::path presetPath = fs::path("out") / (s_.exe + ".preset.json");
    model.onSavePreset = [&, presetPath] {
        auto saved = writeFileAtomically(presetPath, s_.params.toJson());
        const WordArgs file{{"file", presetPath.string()}};
        notify(saved ? say("notice.presetSaved", file) : saved.error());
    };
    model.onLoadPreset = [&, presetPath] {
        auto text = readFile(presetPath, file_limits::preset);
        Status loaded = text ? s_.params.fromJson(*text, presetPath.string()) : Status(Error{text.error()});
        const WordArgs file{{"file", presetPath.string()}};
        notify(loaded ? say("notice.presetLoaded", file) : loaded.error());
    };
    model.measureKnobs = knobSweepStarter(at.extent);
    // Headless too: --press takes the same keys, and an --overlay capture shows what a window would.
    for (const WindowKeyHelp& k : windowKeysHelp())
        model.keys.push_back({words().textOr("keyName." + std::string(k.token), k.key),
                              words().textOr("key." + std::string(k.token), k.action)});
    model.executable = s_.exe;
    if (clock_.paused() && !clock_.held())
        model.clock = say("notice.paused", {{"seconds", secondsText(clock_.seconds())}});
    if (exerciseView_ != ExerciseView::Off && onExerciseStep()) {
        model.compare = s_.exercise->describeView(exerciseView_);
    } else if (compare_ != CompareMode::Off) {
        if (picture_ && picture_->previousStep()) {
            model.compare = say(
                "notice.compare",
                {{"mode", words().textOr(cat("compareMode.", int(compare_)), describeCompareMode(compare_))},
                 {"previous", cat(*picture_->previousStep() + 1)},
                 {"step", cat(s_.step + 1)},
                 {"seconds", secondsText(clock_.seconds())}});
        } else {
            model.compare = say("notice.compareNeedsStep");
        }
    }
    model.pictureScale = pictureScale_.notice({int(at.place.width), int(at.place.height)});
    model.clockRate = clockRateNotice();
    overlay_->draw(model, at.window.width, at.window.height, delta);
}

void FrameLoop::keep(RenderedFrame& rendered, bool lastFrame, bool readFinal, bool screenshot) {
    record_.lastReport = std::move(rendered.report);
    if (lastFrame) record_.lastTextures = std::move(rendered.textures);
    if (!readFinal) return;
    record_.lastFinalBytes = std::move(rendered.finalImage);
    record_.lastFinal = toFloatImage(record_.lastFinalBytes);
    if (screenshot) {
        // Never over an earlier one: the first free number for this lesson and step.
        fs::path shot = nextScreenshotPath("out", s_.exe, s_.step + 1);
        auto written = writePng(shot, record_.lastFinalBytes);
        const WordArgs file{{"file", shot.string()}};
        notify(written ? say("notice.screenshot", file) : written.error());
    }
}

}  // namespace fx
