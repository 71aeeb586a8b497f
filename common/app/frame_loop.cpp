#include "app/frame_loop.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "app/bench.hpp"
#include "app/capture.hpp"
#include "app/facts_panel.hpp"
#include "app/lesson_listing.hpp"
#include "app/lesson_switch.hpp"
#include "app/run_options.hpp"
#include "base/file_io.hpp"
#include "base/log.hpp"
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
      clock_(session.options.timeStep.value_or(1.0 / 60.0)) {
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

void FrameLoop::run() {
    const double timeStep = s_.options.timeStep.value_or(1.0 / 60.0);
    const std::uint64_t frames = std::uint64_t(plan_.frames);
    Clock::time_point lastWall = Clock::now();
    lastReloadCheck_ = lastWall;
    gl::resetDebugCounters();

    for (std::uint64_t index = 0; frames == 0 || index < frames; ++index) {
        context_.pollEvents();
        if (context_.shouldClose()) break;
        if (!plan_.headless && context_.hidden()) {
            // Minimised or unmapped: nothing is seen, so nothing is drawn; sleep until the window
            // system has news (a quarter second at most, so the shader watch still runs).
            context_.waitEvents(0.25);
            lastWall = Clock::now();
            record_.facts.frameCpuMs.push_back(0);
            record_.facts.frameGpuMs.push_back(0);
            continue;
        }
        Clock::time_point frameStart = Clock::now();
        double elapsed =
            plan_.headless ? timeStep : std::chrono::duration<double>(frameStart - lastWall).count();
        lastWall = frameStart;
        if (!takeKeys(frameStart, index)) break;
        const double delta = clock_.advance(elapsed);

        const Size2D window = context_.framebufferSize();
        const bool drawOverlay = overlay_ && overlayVisible_;
        // The picture's place: beside the panels when they show, else the whole window.
        LayoutRect place{0, 0, float(window.width), float(window.height)};
        std::optional<PanelLayout> layout;
        if (drawOverlay && picture_ && !window.empty()) {
            layout = overlay_->layout(window.width, window.height);
            place = layout->picture;
        }
        const Size2D extent = window.empty() ? Size2D{} : Size2D{int(place.width), int(place.height)};
        FrameInfo frame = frameInfo(index, delta, extent, place);
        frame.seconds = clock_.seconds();
        frame.world = renderer_.world(frame.seconds);
        if (SceneWork* work = renderer_.sceneWork()) work->update(frame.seconds, frame.deltaSeconds);
        s_.lesson->update(frame);
        if (extent.empty()) {
            // Minimised (or --size 0x0): nothing to draw into, and aspect = w/0 must not happen.
            if (!plan_.headless) context_.waitEvents(0.25);
            record_.facts.frameCpuMs.push_back(0);
            record_.facts.frameGpuMs.push_back(0);
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
            if (renderedStep_ >= 0 && renderedStep_ != s_.step) picture_->keepAsPrevious(renderedStep_);
            renderedStep_ = s_.step;
            request.target = picture_->target(extent);
        }
        // A sweep asked for by the cost panel measures one setting here, between frames, never inside one.
        if (drawOverlay && overlay_->costPanel().measurePending())
            overlay_->costPanel().runPending(knobSweepStarter());
        RenderedFrame rendered = renderer_.render(
            *s_.lesson, frame, request, [&](const FrameGraph& graph, const FrameReport& report) {
                if (picture_) present(place, window);
                if (drawOverlay) this->drawOverlay(frame, graph, report, delta, window);
            });
        if (!inspectChecked_) {
            inspectChecked_ = true;  // the first frame's graph knows the texture names --inspect can use
            for (const auto& warning : unknownInspectWarnings(s_.options.inspect, rendered.report, s_.step))
                log::warning(warning);
        }
        record_.lastFrame = frame;
        if (lastFrame && picture_) {
            record_.lastPicture = picture_->read();
            record_.lastLayout = layout;
            if (overlay_) record_.textScale = overlay_->textScale();
        }
        keep(rendered, lastFrame, request.readFinal, screenshot);
        context_.present();
        gl::drainErrorFlags();
        record_.facts.frameCpuMs.push_back(
            std::chrono::duration<double, std::milli>(Clock::now() - frameStart).count());
        record_.facts.frameGpuMs.push_back(rendered.passMs);
    }
    // The facts of the last frame read the last frame's report.
    record_.lastFrame.previousFrame = &record_.lastReport;
    s_.windowSize = context_.framebufferSize();
    saveUiSettings();
}

void FrameLoop::present(const LayoutRect& place, Size2D window) {
    // Around the picture (where no panel is, for a moment during a resize): a dark ground.
    gl::DebugGroup group("present picture");
    const GLuint target = context_.presentFramebuffer();
    const float ground[4] = {0.08f, 0.08f, 0.09f, 1.0f};
    glClearNamedFramebufferfv(target, GL_COLOR, 0, ground);
    picture_->present(target, window.height, place, compare_);
}

std::function<std::unique_ptr<SweepRun>()> FrameLoop::knobSweepStarter() {
    return [this]() -> std::unique_ptr<SweepRun> {
        return std::make_unique<KnobSweep>(*s_.lesson, s_.params, renderer_, context_, SweepOptions{}, s_.exe,
                                           s_.step);
    };
}

bool FrameLoop::takeKeys(Clock::time_point now, std::uint64_t index) {
    int stepCount = int(s_.lesson->steps().size());
    KeyPresses keys = input_.takeKeyPresses();
    if (overlay_ && overlay_->wantsKeyboard()) {
        // Typing into one of the overlay's fields: the keys that are characters are the field's.
        keys.next = keys.previous = keys.pause = keys.advanceFrame = false;
        keys.textBigger = keys.textSmaller = false;
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
    if (keys.advanceFrame) clock_.stepOnce();
    if (keys.textBigger) changeTextScale(kTextScaleStep);
    if (keys.textSmaller) changeTextScale(-kTextScaleStep);
    if (keys.resetLayout && overlay_) {
        overlay_->resetLayout();
        s_.status = "layout reset";
        saveUiSettings();
    }
    if (keys.compare) {
        compare_ = picture_ ? nextCompareMode(compare_) : CompareMode::Off;
        s_.status = picture_ ? cat("compare: ", describeCompareMode(compare_)) : "compare: needs a window";
        log::info(s_.status);
    }
    if (keys.findSpecial && overlay_) {
        overlay_->inspector().setOpen(true);
        overlay_->inspector().findNextSpecial();
    }
    if (overlay_) {
        // Esc stops the cost panel's sweep rather than the app while one runs.
        if (keys.cancel) overlay_->costPanel().cancel();
        input_.setEscapeCancels(overlay_->costPanel().measurePending());
    }
    screenshotAsked_ = keys.screenshot;
    if (!plan_.headless && now - lastReloadCheck_ > std::chrono::milliseconds(500)) {
        lastReloadCheck_ = now;
        programs_.reloadChanged();
        if (lessonText_) (void)lessonText_->reloadIfChanged();
    }
    if (keys.reload) {
        programs_.reloadAll();
        s_.status = "reloaded shaders";
    }
    if (keys.nextLesson || keys.previousLesson) {
        const int direction = keys.nextLesson ? 1 : -1;
        if (neighbourLesson(s_.exe, direction)) {
            s_.switchLesson = direction;
            return false;
        }
        s_.status = direction > 0 ? "this is the last lesson" : "this is the first lesson";
    }
    return !keys.quit;
}

void FrameLoop::changeTextScale(float by) {
    if (!overlay_) return;
    const float scale = clampTextScale(overlay_->textScale() + by);
    overlay_->setTextScale(scale);
    s_.status = cat("text scale ", scale);
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

FrameInfo FrameLoop::frameInfo(std::uint64_t index, double delta, Size2D extent,
                               const LayoutRect& place) const {
    FrameInfo frame;
    frame.index = index;
    frame.deltaSeconds = delta;
    frame.size = extent;
    frame.step = s_.step;
    frame.seed = s_.options.seed;
    frame.headless = plan_.headless;
    frame.previousFrame = index > 0 ? &record_.lastReport : nullptr;
    frame.pointer = input_.pointer(context_.framebufferSize(), int(place.x), int(place.y), extent,
                                   overlay_ && overlayVisible_ && overlay_->wantsMouse());
    return frame;
}

void FrameLoop::drawOverlay(const FrameInfo& frame, const FrameGraph& graph, const FrameReport& report,
                            double delta, Size2D window) {
    glBindFramebuffer(GL_FRAMEBUFFER, context_.presentFramebuffer());
    glViewport(0, 0, window.width, window.height);
    Lesson& lesson = *s_.lesson;
    OverlayModel model;
    model.title = cat(lesson.info().number, ". ", lesson.info().title);
    if (lessonText_) {
        model.steps = lessonText_->steps();
        model.textError = lessonText_->error();
        model.textRevision = lessonText_->revision();
        model.language = lessonText_->language();
        model.languages = lessonText_->available();
        model.setLanguage = [this](const std::string& language) { (void)lessonText_->setLanguage(language); };
    }
    model.step = &s_.step;
    model.params = &s_.params;
    model.frame = &report;
    model.graph = &graph;
    model.cameraNear = s_.scene.camera.near;
    model.cameraFar = s_.scene.camera.far;
    model.timing = cat(toString(renderer_.timer().method()));
    model.renderer = cat(context_.renderer(), " (", context_.kind(), ")");
    model.frameMs = record_.facts.frameCpuMs.empty() ? 0 : record_.facts.frameCpuMs.back();
    model.glErrors = gl::debugCounters().errors;
    model.glExpectedErrors = gl::debugCounters().expectedErrors;
    model.shaderErrors = programs_.errors();
    model.status = s_.status;
    model.lessonPanel = [&] {
        Facts facts;
        lesson.facts(facts, frame);
        drawFacts(facts);
        lesson.drawPanel(frame);
    };
    fs::path presetPath = fs::path("out") / (s_.exe + ".preset.json");
    model.onSavePreset = [&, presetPath] {
        auto saved = writeFileAtomically(presetPath, s_.params.toJson());
        s_.status = saved ? cat("saved ", presetPath.string()) : saved.error();
    };
    model.onLoadPreset = [&, presetPath] {
        auto text = readFile(presetPath, file_limits::preset);
        Status loaded = text ? s_.params.fromJson(*text, presetPath.string()) : Status(Error{text.error()});
        s_.status = loaded ? cat("loaded ", presetPath.string()) : loaded.error();
    };
    model.measureKnobs = knobSweepStarter();
    // Headless too: --press takes the same keys, and an --overlay capture shows what a window would.
    for (const WindowKeyHelp& k : windowKeysHelp()) model.keys.push_back({k.key, k.action});
    model.executable = s_.exe;
    if (clock_.paused())
        model.clock =
            cat("paused at ", secondsText(clock_.seconds()), " s (space resumes, . steps one frame)");
    if (compare_ != CompareMode::Off) {
        model.compare =
            picture_ && picture_->previousStep()
                ? cat("compare: ", describeCompareMode(compare_), " (step ", *picture_->previousStep() + 1,
                      " against step ", s_.step + 1, "; F3 changes)")
                : "compare: change the step (arrows) to keep a picture to compare with";
    }
    overlay_->draw(model, window.width, window.height, delta);
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
        s_.status = written ? cat("saved ", shot.string()) : written.error();
        log::info(s_.status);
    }
}

}  // namespace fx
