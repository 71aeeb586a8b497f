#include "app/runner.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <thread>


#include "app/bench.hpp"
#include "app/capture.hpp"
#include "app/frame_renderer.hpp"
#include "app/lesson_listing.hpp"
#include "app/window_input.hpp"
#include "app/run_options.hpp"
#include "app/run_report.hpp"
#include "base/file_io.hpp"
#include "base/log.hpp"
#include "base/paths.hpp"
#include "gl/context_guard.hpp"
#include "gl/debug_output.hpp"
#include "gl/readback.hpp"
#include "image/png_file.hpp"
#include "platform/context.hpp"
#include "render_gl/gl_pass_executor.hpp"
#include "render_gl/gl_texture_allocator.hpp"
#include "scene/scene_loader.hpp"
#include "scene/scene_post.hpp"
#include "ui/overlay.hpp"

namespace fx {
namespace {

namespace fs = std::filesystem;

struct Session {
    Lesson& lesson;
    RunOptions options;
    ParamSet params;
    Scene scene;
    int step = 0;
    std::string status;
};

int run(Session& s, const std::string& exe) {
    const RunOptions& o = s.options;
    bool headless = o.forceHeadless || o.bench;  // the bench measures a fixed headless frame
    if (!headless && !displayAvailable()) {
        headless = true;
        log::info("no display found: rendering headless");
    }
    fs::path captureDir = o.captureDir;
    fs::path reportFile = o.reportFile;
    if (headless && captureDir.empty() && reportFile.empty()) {
        // A new user's first run with no display still shows something: the picture and the report.
        captureDir = fs::path("out") / exe;
        reportFile = captureDir / "report.json";
    }
    int frames = o.frames.value_or(headless ? 3 : 0);  // 0: until the window closes

    ContextOptions co;
    co.size = {o.width.value_or(headless ? 1280 : 1280), o.height.value_or(720)};
    co.title = cat("fxlab ", s.lesson.info().number, ": ", s.lesson.info().title);
    Result<std::unique_ptr<Context>> made = headless ? createHeadlessContext(co) : createWindowContext(co);
    if (!made && !headless) {
        log::warning(made.error(), "; trying headless instead");
        headless = true;
        made = createHeadlessContext(co);
    }
    if (!made) {
        log::error(made.error());
        return 1;
    }
    std::unique_ptr<Context> context = std::move(*made);
    if (headless && (co.size.width == 0 || co.size.height == 0)) context->resize({co.size.width, co.size.height});

    WindowInput input(context->window());  // before the overlay, which chains its key callback

    int exitCode = 0;
    {
        if (auto status = s.lesson.init(s.scene); !status) {
            log::error(exe, ": ", status.error());
            s.lesson.shutdown();
            return 1;
        }
        FrameRenderer renderer(*context, o.timing, !o.bench);
        PassTimer& timer = renderer.timer();
        if (o.bench) {
            if (!o.benchKnob.empty() && (!s.params.find(o.benchKnob) || !s.params.find(o.benchKnob)->knob)) {
                std::string knobs;
                for (auto* k : s.params.knobs()) knobs += (knobs.empty() ? "" : ", ") + k->name;
                log::error(exe, ": --knob: no quality knob named \"", o.benchKnob, "\"; this lesson has: ",
                           knobs.empty() ? "(none)" : knobs);
                s.lesson.shutdown();
                return 2;
            }
            fs::path dir = o.benchOut.empty() ? fs::path("out") / "bench" / lessonFolderName(s.lesson.info()) : o.benchOut;
            SweepResult result = sweepKnobs(s.lesson, s.params, renderer, *context,
                                            {o.benchKnob, o.benchFrames, o.benchValues}, exe,
                                            !o.step && s.lesson.benchStep() >= 0 ? s.lesson.benchStep() : s.step);
            std::cout << describeSweep(result);
            if (auto written = writeBenchOutputs(result, dir); !written) {
                log::error(written.error());
                exitCode = 1;
            } else {
                log::info("bench results written to ", dir.string(), "/");
            }
            if (gl::debugCounters().errors > 0) {
                log::error(gl::debugCounters().errors, " GL error(s) during the bench: ", gl::debugCounters().lastError);
                exitCode = 1;
            }
            s.lesson.shutdown();
            return exitCode;
        }
        std::unique_ptr<Overlay> overlay;
        if (!headless || o.overlayHeadless) overlay = std::make_unique<Overlay>(context->window());
        bool overlayVisible = headless ? o.overlayHeadless : o.overlay;
        if (overlay && !o.inspect.empty()) {
            // --inspect NAME with the overlay shows that texture in the inspector from the start.
            overlay->inspector().setOpen(true);
            overlay->inspector().select(o.inspect.front());
        }

        RunFacts facts;
        facts.lesson = exe;
        facts.contextKind = context->kind();
        facts.renderer = context->renderer();
        facts.glVersion = context->version();
        facts.timingMethod = std::string(toString(timer.method()));
        facts.timingReason = timer.reason();
        facts.scene = s.scene.file.string();

        double timeStep = o.timeStep.value_or(1.0 / 60.0);
        double seconds = 0;
        auto wallStart = std::chrono::steady_clock::now();
        auto lastWall = wallStart;
        auto lastReloadCheck = wallStart;
        FrameReport lastReport;
        std::vector<CapturedTexture> lastTextures;
        FloatImage lastFinal;
        ByteImage lastFinalBytes;
        int screenshotCount = 0;
        gl::resetDebugCounters();

        for (std::uint64_t index = 0; frames == 0 || index < std::uint64_t(frames); ++index) {
            context->pollEvents();
            if (context->shouldClose()) break;
            auto frameStart = std::chrono::steady_clock::now();
            double delta = headless ? timeStep : std::chrono::duration<double>(frameStart - lastWall).count();
            lastWall = frameStart;
            seconds += delta;

            int stepCount = int(s.lesson.steps().size());
            KeyPresses keys = input.takeKeyPresses();
            if (keys.next && !(overlay && overlay->wantsKeyboard())) s.step = std::min(s.step + 1, stepCount - 1);
            if (keys.previous && !(overlay && overlay->wantsKeyboard())) s.step = std::max(s.step - 1, 0);
            if (keys.toggleOverlay) overlayVisible = !overlayVisible;
            bool reloadNow = keys.reload;
            bool screenshot = keys.screenshot;
            if (!headless && frameStart - lastReloadCheck > std::chrono::milliseconds(500)) {
                lastReloadCheck = frameStart;
                for (auto* p : s.lesson.programs()) p->reloadIfChanged();
            }
            if (reloadNow) {
                for (auto* p : s.lesson.programs()) (void)p->reload();
                s.status = "reloaded shaders";
            }

            Extent extent = context->framebufferSize();
            FrameInfo frame;
            frame.index = index;
            frame.seconds = seconds;
            frame.deltaSeconds = delta;
            frame.size = {extent.width, extent.height};
            frame.step = s.step;
            frame.seed = o.seed;
            frame.headless = headless;
            frame.previousFrame = index > 0 ? &lastReport : nullptr;
            frame.pointer = input.pointer(extent, overlay && overlayVisible && overlay->wantsMouse());
            s.lesson.update(frame);
            if (extent.empty()) {
                // Minimised (or --size 0x0): nothing to draw into, and aspect = w/0 must not happen.
                if (!headless) std::this_thread::sleep_for(std::chrono::milliseconds(50));
                facts.frameCpuMs.push_back(0);
                facts.frameGpuMs.push_back(0);
                continue;
            }
            bool lastFrame = frames != 0 && index + 1 == std::uint64_t(frames);
            bool drawOverlay = overlay && overlayVisible;
            FrameRequest request;
            request.inspect = o.inspect;
            // What the inspector shows stays alive, with the passes that make it.
            if (drawOverlay) {
                for (auto& name : overlay->wantedTextures()) request.inspect.push_back(name);
            }
            request.readTextures = lastFrame;
            request.readFinal = lastFrame || screenshot;
            auto drawOverlayOnTop = [&](const FrameGraph& graph, const FrameReport& report) {
                if (!drawOverlay) return;
                glBindFramebuffer(GL_FRAMEBUFFER, context->presentFramebuffer());
                glViewport(0, 0, extent.width, extent.height);
                OverlayModel model;
                model.title = cat(s.lesson.info().number, ". ", s.lesson.info().title);
                for (auto& st : s.lesson.steps()) model.steps.push_back({st.title, st.text});
                model.step = &s.step;
                model.params = &s.params;
                model.frame = &report;
                model.graph = &graph;
                model.cameraNear = s.scene.camera.near;
                model.cameraFar = s.scene.camera.far;
                model.timing = cat(toString(timer.method()));
                model.renderer = cat(context->renderer(), " (", context->kind(), ")");
                model.frameMs = facts.frameCpuMs.empty() ? 0 : facts.frameCpuMs.back();
                model.glErrors = gl::debugCounters().errors;
                model.glExpectedErrors = gl::debugCounters().expectedErrors;
                for (auto* p : s.lesson.programs()) {
                    if (!p->error().empty()) model.shaderErrors.push_back(p->error());
                }
                model.status = s.status;
                model.lessonPanel = [&] { s.lesson.drawPanel(frame); };
                fs::path presetPath = fs::path("out") / (exe + ".preset.json");
                model.onSavePreset = [&, presetPath] {
                    auto saved = writeFileAtomically(presetPath, s.params.toJson());
                    s.status = saved ? cat("saved ", presetPath.string()) : saved.error();
                };
                model.onLoadPreset = [&, presetPath] {
                    auto text = readTextFile(presetPath);
                    Status loaded = text ? s.params.fromJson(*text, presetPath.string()) : Status(Error{text.error()});
                    s.status = loaded ? cat("loaded ", presetPath.string()) : loaded.error();
                };
                model.measureKnobs = [&] {
                    return sweepKnobs(s.lesson, s.params, renderer, *context, {{}, 3, 0}, exe, s.step);
                };
                overlay->draw(model, extent.width, extent.height, delta);
            };
            // A sweep asked for by the cost panel runs here, between frames, never inside one.
            if (drawOverlay && overlay->costPanel().measurePending()) {
                overlay->costPanel().runPending(
                    [&] { return sweepKnobs(s.lesson, s.params, renderer, *context, {{}, 3, 0}, exe, s.step); });
            }
            RenderedFrame rendered = renderer.render(s.lesson, frame, request, drawOverlayOnTop);
            lastReport = std::move(rendered.report);
            double passMs = rendered.passMs;
            if (lastFrame) lastTextures = std::move(rendered.textures);
            if (request.readFinal) {
                lastFinalBytes = std::move(rendered.finalImage);
                lastFinal = toFloatImage(lastFinalBytes);
                if (screenshot) {
                    fs::path shot = fs::path("out") / cat(exe, "-screenshot-", ++screenshotCount, ".png");
                    auto written = writePng(shot, lastFinalBytes);
                    s.status = written ? cat("saved ", shot.string()) : written.error();
                    log::info(s.status);
                }
            }
            context->present();
            gl::drainErrorFlags();
            facts.frameCpuMs.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - frameStart).count());
            facts.frameGpuMs.push_back(passMs);
        }

        // The results of the run.
        Extent extent = context->framebufferSize();
        facts.size = {extent.width, extent.height};
        facts.step = s.step + 1;
        auto steps = s.lesson.steps();
        facts.stepTitle = s.step < int(steps.size()) ? steps[std::size_t(s.step)].title : "";
        facts.glErrors = gl::debugCounters().errors;
        facts.glExpectedErrors = gl::debugCounters().expectedErrors;
        facts.glWarnings = gl::debugCounters().warnings;
        facts.lastGlError = gl::debugCounters().lastError;
        for (auto* p : s.lesson.programs()) {
            if (!p->error().empty()) facts.shaderErrors.push_back(p->error());
        }
        s.lesson.reportFacts(facts.lessonFacts);
        for (const Param& p : s.params.all())
            facts.params.push_back({p.name, p.text(), std::string(toString(p.source()))});
        if (!captureDir.empty()) {
            if (auto written = writeCaptures(captureDir, lastFinalBytes, lastTextures, o.captureFloat); !written) {
                log::error(written.error());
                exitCode = 1;
            } else {
                log::info("captures written to ", captureDir.string(), "/ (final.png and ", lastTextures.size(),
                          " intermediate textures)");
            }
        }
        if (!reportFile.empty()) {
            auto json = buildRunReport(facts, lastReport, lastTextures, lastFinal).dump(2) + "\n";
            if (auto written = writeFileAtomically(reportFile, json); !written) {
                log::error(written.error());
                exitCode = 1;
            } else {
                log::info("report written to ", reportFile.string());
            }
        }
        if (facts.glErrors > 0) log::error(facts.glErrors, " GL error(s) in this run; the last: ", facts.lastGlError);
        s.lesson.shutdown();
        // overlay, executor, pool and allocator go here, while the context is still current.
    }
    return exitCode;
}

}  // namespace

int runLesson(Lesson& lesson, int argc, char** argv) {
    std::string exe = executableName(lesson.info());
    std::vector<std::string> args(argv + 1, argv + argc);
    auto parsed = parseRunOptions(args);
    if (!parsed) {
        std::cerr << exe << ": " << parsed.error() << "\n";
        return 2;
    }
    Session s{lesson, std::move(*parsed), {}, {}, 0, {}};
    lesson.declareParams(s.params);
    if (s.options.help) {
        std::cout << lesson.info().title << "\n\n" << runOptionsHelp(exe);
        return 0;
    }
    if (s.options.listSteps) {
        printSteps(lesson.steps());
        return 0;
    }
    int stepCount = int(lesson.steps().size());
    if (s.options.step) {
        if (*s.options.step > stepCount) {
            std::cerr << exe << ": --step: expected a step number from 1 to " << stepCount << ", got " << *s.options.step << "\n";
            return 2;
        }
        s.step = *s.options.step - 1;
    }
    // The scene first: its settings are the parameters' starting values, which a preset and the
    // command line then override. None of this needs GL, so --list-params shows the result.
    fs::path sceneFile = s.options.scene.empty() ? resourceDir() / lesson.info().defaultScene : s.options.scene;
    auto scene = loadScene(sceneFile);
    if (!scene) {
        std::cerr << exe << ": " << scene.error() << "\n";
        return 1;
    }
    s.scene = std::move(*scene);
    std::vector<SettingText> sceneSettings = postEffectSettings(s.scene.postEffects);
    if (auto applied = s.params.applyScene(sceneSettings, postEffectSettingPaths(), sceneFile.string()); !applied) {
        std::cerr << exe << ": " << applied.error() << "\n";
        return 2;
    }
    if (auto unused = s.params.unusedSettings(sceneSettings); !unused.empty()) {
        std::string list;
        for (const std::string& setting : unused) list += (list.empty() ? "" : ", ") + setting;
        log::info(sceneFile.filename().string(), ": no parameter of this lesson starts from ", list);
    }
    if (!s.options.presetFile.empty()) {
        auto text = readTextFile(s.options.presetFile);
        Status loaded = text ? s.params.fromJson(*text, s.options.presetFile.string()) : Status(Error{text.error()});
        if (!loaded) {
            std::cerr << exe << ": --preset: " << loaded.error() << "\n";
            return 2;
        }
    }
    for (const std::string& assignment : s.options.params) {
        if (auto status = s.params.assign(assignment); !status) {
            std::cerr << exe << ": --param: " << status.error() << "\n";
            return 2;
        }
    }
    s.params.markStartingValues();  // what the overlay's Reset returns to
    if (s.options.listParams) {
        printParams(s.params);
        return 0;
    }
    return run(s, exe);
}

}  // namespace fx
