#include "app/frame_loop.hpp"

#include <algorithm>
#include <filesystem>
#include <thread>

#include "app/bench.hpp"
#include "app/facts_panel.hpp"
#include "app/lesson_listing.hpp"
#include "app/run_options.hpp"
#include "base/file_io.hpp"
#include "base/log.hpp"
#include "gl/debug_output.hpp"
#include "image/png_file.hpp"

namespace fx {

namespace fs = std::filesystem;

FrameLoop::FrameLoop(RunSession& session, const RunPlan& plan, Context& context, FrameRenderer& renderer,
                     WindowInput& input, Overlay* overlay, gl::ProgramRegistry& programs)
    : s_(session),
      plan_(plan),
      context_(context),
      renderer_(renderer),
      input_(input),
      overlay_(overlay),
      programs_(programs),
      overlayVisible_(plan.headless ? session.options.overlayHeadless : session.options.overlay) {
    RunFacts& facts = record_.facts;
    facts.lesson = s_.exe;
    facts.contextKind = context.kind();
    facts.renderer = context.renderer();
    facts.glVersion = context.version();
    facts.timingMethod = std::string(toString(renderer.timer().method()));
    facts.timingReason = renderer.timer().reason();
    facts.scene = s_.scene.file.string();
    // The steps' text from lesson.md (or lesson.ja.md), for the overlay; read again when saved.
    if (overlay_) {
        lessonText_.emplace(lessonSourceFolder(s_.lesson->info()), s_.lesson->steps(), s_.options.language);
        (void)lessonText_->reloadIfChanged();
    }
}

void FrameLoop::run() {
    const double timeStep = s_.options.timeStep.value_or(1.0 / 60.0);
    const std::uint64_t frames = std::uint64_t(plan_.frames);
    double seconds = 0;
    Clock::time_point lastWall = Clock::now();
    lastReloadCheck_ = lastWall;
    gl::resetDebugCounters();

    for (std::uint64_t index = 0; frames == 0 || index < frames; ++index) {
        context_.pollEvents();
        if (context_.shouldClose()) break;
        Clock::time_point frameStart = Clock::now();
        double delta =
            plan_.headless ? timeStep : std::chrono::duration<double>(frameStart - lastWall).count();
        lastWall = frameStart;
        seconds += delta;
        takeKeys(frameStart);

        Size2D extent = context_.framebufferSize();
        FrameInfo frame = frameInfo(index, delta, extent);
        frame.seconds = seconds;
        if (SceneWork* work = renderer_.sceneWork()) work->update(frame.seconds, frame.deltaSeconds);
        s_.lesson->update(frame);
        if (extent.empty()) {
            // Minimised (or --size 0x0): nothing to draw into, and aspect = w/0 must not happen.
            if (!plan_.headless) std::this_thread::sleep_for(std::chrono::milliseconds(50));
            record_.facts.frameCpuMs.push_back(0);
            record_.facts.frameGpuMs.push_back(0);
            continue;
        }
        const bool lastFrame = frames != 0 && index + 1 == frames;
        const bool drawOverlay = overlay_ && overlayVisible_;
        const bool screenshot = std::exchange(screenshotAsked_, false);
        FrameRequest request;
        request.inspect = s_.options.inspect;
        // What the inspector shows stays alive, with the passes that make it.
        if (drawOverlay) {
            for (auto& name : overlay_->wantedTextures()) request.inspect.push_back(name);
        }
        request.readTextures = lastFrame;
        request.readFinal = lastFrame || screenshot;
        // A sweep asked for by the cost panel measures one setting here, between frames, never inside one.
        if (drawOverlay && overlay_->costPanel().measurePending())
            overlay_->costPanel().runPending(knobSweepStarter());
        RenderedFrame rendered = renderer_.render(*s_.lesson, frame, request,
                                                  [&](const FrameGraph& graph, const FrameReport& report) {
                                                      if (drawOverlay)
                                                          this->drawOverlay(frame, graph, report, delta);
                                                  });
        if (!inspectChecked_) {
            inspectChecked_ = true;  // the first frame's graph knows the texture names --inspect can use
            for (const auto& warning : unknownInspectWarnings(s_.options.inspect, rendered.report, s_.step))
                log::warning(warning);
        }
        record_.lastFrame = frame;
        keep(rendered, lastFrame, request.readFinal, screenshot);
        context_.present();
        gl::drainErrorFlags();
        record_.facts.frameCpuMs.push_back(
            std::chrono::duration<double, std::milli>(Clock::now() - frameStart).count());
        record_.facts.frameGpuMs.push_back(rendered.passMs);
    }
    // The facts of the last frame read the last frame's report.
    record_.lastFrame.previousFrame = &record_.lastReport;
}

std::function<std::unique_ptr<SweepRun>()> FrameLoop::knobSweepStarter() {
    return [this]() -> std::unique_ptr<SweepRun> {
        return std::make_unique<KnobSweep>(*s_.lesson, s_.params, renderer_, context_, SweepOptions{}, s_.exe,
                                           s_.step);
    };
}

void FrameLoop::takeKeys(Clock::time_point now) {
    int stepCount = int(s_.lesson->steps().size());
    KeyPresses keys = input_.takeKeyPresses();
    bool keysForUs = !(overlay_ && overlay_->wantsKeyboard());
    if (keys.next && keysForUs) s_.step = std::min(s_.step + 1, stepCount - 1);
    if (keys.previous && keysForUs) s_.step = std::max(s_.step - 1, 0);
    if (keys.toggleOverlay) overlayVisible_ = !overlayVisible_;
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
}

FrameInfo FrameLoop::frameInfo(std::uint64_t index, double delta, Size2D extent) const {
    FrameInfo frame;
    frame.index = index;
    frame.deltaSeconds = delta;
    frame.size = extent;
    frame.step = s_.step;
    frame.seed = s_.options.seed;
    frame.headless = plan_.headless;
    frame.previousFrame = index > 0 ? &record_.lastReport : nullptr;
    frame.pointer = input_.pointer(extent, overlay_ && overlayVisible_ && overlay_->wantsMouse());
    return frame;
}

void FrameLoop::drawOverlay(const FrameInfo& frame, const FrameGraph& graph, const FrameReport& report,
                            double delta) {
    glBindFramebuffer(GL_FRAMEBUFFER, context_.presentFramebuffer());
    glViewport(0, 0, frame.size.width, frame.size.height);
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
    overlay_->draw(model, frame.size.width, frame.size.height, delta);
}

void FrameLoop::keep(RenderedFrame& rendered, bool lastFrame, bool readFinal, bool screenshot) {
    record_.lastReport = std::move(rendered.report);
    if (lastFrame) record_.lastTextures = std::move(rendered.textures);
    if (!readFinal) return;
    record_.lastFinalBytes = std::move(rendered.finalImage);
    record_.lastFinal = toFloatImage(record_.lastFinalBytes);
    if (screenshot) {
        fs::path shot = fs::path("out") / cat(s_.exe, "-screenshot-", ++screenshotCount_, ".png");
        auto written = writePng(shot, record_.lastFinalBytes);
        s_.status = written ? cat("saved ", shot.string()) : written.error();
        log::info(s_.status);
    }
}

}  // namespace fx
