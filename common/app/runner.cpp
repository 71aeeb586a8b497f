#include "app/runner.hpp"
#include "app/process_start.hpp"

#include <filesystem>
#include <iostream>
#include <optional>

#include "app/bench_mode.hpp"
#include "app/exercise_session.hpp"
#include "app/frame_loop.hpp"
#include "app/lesson_listing.hpp"
#include "app/lesson_switch.hpp"
#include "app/lesson_text_files.hpp"
#include "app/renderdoc_session.hpp"
#include "app/run_context.hpp"
#include "app/run_results.hpp"
#include "base/fatal_error.hpp"
#include "base/file_io.hpp"
#include "base/log.hpp"
#include "base/paths.hpp"
#include "base/words.hpp"
#include "effects/scene/scene_work.hpp"
#include "gl/shader_dump.hpp"
#include "scene/scene_loader.hpp"
#include "scene/scene_post.hpp"
#include "scene/scene_settings.hpp"

namespace fx {
namespace {

namespace fs = std::filesystem;

// The lesson's Gpu<T> members (its effects), init, then the check that every program they built is
// usable.
Status initLesson(RunSession& s, const gl::ProgramRegistry& programs) {
    s.lesson->buildGpuMembers(s.scene);
    if (Status status = s.lesson->init(s.scene); !status) return status;
    if (auto error = programs.firstUnusable()) return Error{*error};
    return Status::success();
}

int run(RunSession& s) {
    const RunOptions& o = s.options;
    RunPlan plan = planRun(o, s.exe);
    if (!plan.headless) s.ui = loadUiSettings(uiSettingsPath());
    if (!o.renderdoc.empty()) {
        // RenderDoc hooks GL only when it is in the process before GL is: this program starts again
        // with it preloaded (platform/renderdoc_api.hpp).
        auto restart = prepareRenderDocStart();
        if (!restart) {
            log::error(s.exe, ": ", restart.error());
            return 1;
        }
        if (*restart) {
            Error failed = execLesson(runningExecutable(), s.args);
            log::error(s.exe, ": --renderdoc: could not start again with RenderDoc: ", failed.message);
            return 1;
        }
        auto renderdoc = RenderDocSession::open(o, plan.frames);
        if (!renderdoc) {
            log::error(s.exe, ": ", renderdoc.error());
            return 1;
        }
        s.renderdoc = std::move(*renderdoc);
    }
    auto made = openRunContext(s, plan);
    if (!made) {
        log::error(made.error());
        return 1;
    }
    std::unique_ptr<Context> context = std::move(*made);
    WindowInput input(context->window());  // before the overlay, which chains its key callback
    gl::ProgramRegistry programs;          // every program built from here on joins it
    // From here on every way out destroys the lesson first, while the context is still current;
    // the renderer (executor, pool) and the overlay, declared later, go before it.
    LessonRelease release(s);
    // The scene's meshes on the GPU, drawn by every pass that draws the scene (FrameInfo::world); they
    // go before the lesson, with the context current.
    SceneMeshes meshes(s.scene);
    if (Status ready = initLesson(s, programs); !ready) {
        log::error(s.exe, ": ", ready.error());
        return 1;
    }
    SceneWork work(s.scene);
    FrameRenderer renderer(*context, o.timing, !o.bench);
    renderer.setSceneWork(&work);
    renderer.setScene(s.scene, meshes);
    // Animation and GPU skinning once a frame, only when the scene has skinned meshes.
    work.onUpdate(Simulation::animation, "skinning",
                  [&meshes](const SimulationStep& step) { meshes.update(step.seconds); });
    s.lesson->simulations(work);
    if (o.bench) return runBenchMode(s, renderer, *context);

    std::unique_ptr<Overlay> overlay;
    if (!plan.headless || o.overlayHeadless) overlay = std::make_unique<Overlay>(context->window());
    if (overlay && !o.inspect.empty()) {
        // --inspect NAME with the overlay shows that texture in the inspector from the start.
        overlay->inspector().setOpen(true);
        overlay->inspector().select(o.inspect.front());
    }
    FrameLoop loop(s, plan, *context, renderer, input, overlay.get(), programs);
    loop.run();
    // Page Down / Page Up: the next lesson writes the captures and the report asked for, not this one.
    if (s.switchLesson != 0) return 0;
    const int code = writeRunResults(s, plan, *context, programs, loop.record());
    if (s.renderdoc) {
        if (Status captured = s.renderdoc->finish(); !captured) {
            log::error(s.exe, ": ", captured.error());
            return code == 0 ? 1 : code;
        }
    }
    return code;
}

// The scene first: its settings are the parameters' starting values, which a preset and the command
// line then override (setParameters). None of this needs GL, so --list-params shows the result.
// Returns the exit code when the run cannot go on.
std::optional<int> loadLessonScene(RunSession& s) {
    const LessonInfo info = s.lesson->info();
    if (s.options.scene.empty() && info.defaultScene.empty()) {
        // A lesson that names no scene runs with an empty one: the default camera and background,
        // no objects or lights, and every pass that needs a scene feature not called for.
        log::info(s.exe,
                  ": this lesson names no scene (LessonInfo::defaultScene); running with an empty one");
        return std::nullopt;
    }
    fs::path sceneFile = s.options.scene.empty() ? resourceDir() / info.defaultScene : s.options.scene;
    auto scene = loadScene(sceneFile);
    if (!scene) {
        std::cerr << s.exe << ": " << scene.error() << "\n";
        return 1;
    }
    s.scene = std::move(*scene);
    const std::vector<SettingText> settings = sceneSettings(s.scene);
    if (auto applied = s.params.applyScene(settings, sceneSettingPaths(), sceneFile.string()); !applied) {
        std::cerr << s.exe << ": " << applied.error() << "\n";
        return 2;
    }
    if (auto unused = s.params.unusedSettings(settings, sceneSettingDefaults()); !unused.empty()) {
        std::string list;
        for (const std::string& setting : unused) list += (list.empty() ? "" : ", ") + setting;
        log::info(sceneFile.filename().string(),
                  ": this lesson reads other settings of the same effect, but none of ", list,
                  " (no parameter of this lesson starts from it)");
    }
    return std::nullopt;
}

// --preset, then every --param; what they leave is what the overlay's Reset returns to.
std::optional<int> setParameters(RunSession& s) {
    if (!s.options.presetFile.empty()) {
        auto text = readFile(s.options.presetFile, file_limits::preset);
        Status loaded =
            text ? s.params.fromJson(*text, s.options.presetFile.string()) : Status(Error{text.error()});
        if (!loaded) {
            std::cerr << s.exe << ": --preset: " << loaded.error() << "\n";
            return 2;
        }
    }
    for (const std::string& assignment : s.options.params) {
        if (auto status = s.params.assign(assignment); !status) {
            std::cerr << s.exe << ": --param: " << status.error() << "\n";
            return 2;
        }
    }
    s.params.markStartingValues();
    return std::nullopt;
}

// --all-steps: this executable once per step, each writing DIR/step-K/ (lesson_switch.hpp).
int captureEveryStep(const RunSession& s) {
    const int steps = int(s.lesson->steps().size());
    const fs::path self = runningExecutable();
    int failures = 0;
    for (int step = 1; step <= steps; ++step) {
        // DIR/step-K is made here, under the rule for every file written: a link there is not followed
        // out of DIR (the step's own run would take the folder as given).
        if (Status made = makeFolderIn(s.options.captureDir, cat("step-", step)); !made) {
            log::error(made.error());
            ++failures;
            continue;
        }
        auto code = runAndWait(self, stepCaptureArguments(s.args, s.options.captureDir, step));
        if (!code || *code != 0) {
            log::error(s.exe, ": step ", step,
                       code ? cat(" exited with code ", *code) : cat(": ", code.error()));
            ++failures;
        }
    }
    log::info(s.exe, ": ", steps - failures, " of ", steps, " steps captured into ",
              s.options.captureDir.string(), "/step-1 ... step-", steps);
    return failures == 0 ? 0 : 1;
}

}  // namespace

int runLesson(std::unique_ptr<Lesson> owned, LessonInfo info, int argc, char** argv) {
    Lesson& lesson = *owned;
    lesson.setInfo(std::move(info));
    std::string exe = executableName(lesson.info());
    installFatalErrorHandler(exe);
    Doing doing(cat("running ", exe));
    std::vector<std::string> args = programArguments(argc, argv);
    auto parsed = parseRunOptions(args, int(lesson.steps().size()));
    if (!parsed) {
        std::cerr << exe << ": " << parsed.error() << "\n";
        return 2;
    }
    RunSession s{std::move(owned), exe, std::move(*parsed), {}, {}, 0, {}, args, {}, 0, {}, {}, {}};
    // The words a student reads (the panel, the facts' labels, the parameters' help), in --lang's language.
    if (auto loaded = Words::load(lessonSourceFolder(lesson.info()), s.options.language); !loaded) {
        std::cerr << exe << ": " << loaded.error() << "\n";
        return 2;
    } else {
        useWords(std::move(*loaded));
    }
    lesson.declareParams(s.params);
    if (s.options.help) {
        std::cout << lesson.info().title << "\n\n" << runOptionsHelp(exe);
        return 0;
    }
    if (s.options.listSteps) {
        LessonTextFiles text(lessonSourceFolder(lesson.info()), lesson.steps(), s.options.language);
        (void)text.reloadIfChanged();
        return printSteps(text) ? 0 : 1;
    }
    if (s.options.allSteps) return captureEveryStep(s);
    if (s.options.exercise) {
        // Before init: the lesson's programs build from the student's file from the first frame.
        auto exercise = ExerciseSession::open(lesson.info(), *s.options.exercise, s.options.language);
        if (!exercise) {
            std::cerr << exe << ": --exercise: " << exercise.error() << "\n";
            return 2;
        }
        s.exercise = std::move(*exercise);
        s.step = std::min(s.exercise->step(), int(lesson.steps().size()) - 1);
    }
    if (s.options.step) s.step = *s.options.step - 1;  // checked against the lesson's steps when parsed
    if (s.exercise && s.exercise->studentFileIsAScene() && s.options.scene.empty()) {
        // The lesson runs with the student's scene; one that does not load leaves the lesson's own, and
        // the exercise's verdict shows the loader's message.
        s.options.scene = s.exercise->studentFile();
        if (loadLessonScene(s)) {
            log::warning(s.exe, ": exercise: your scene did not load; running with the lesson's own");
            s.options.scene.clear();
        }
    }
    if (auto failed = loadLessonScene(s)) return *failed;
    if (auto failed = setParameters(s)) return *failed;
    if (s.options.listParams) {
        printParams(s.params);
        // Every parameter's words in the language asked for (the unit tests unit.words.<lesson>.<lang>).
        for (const std::string& key : missingWords())
            std::cerr << exe << ": no words for '" << key << "' in " << words().language() << "\n";
        return missingWords().empty() ? 0 : 1;
    }
    if (auto dumping = gl::setShaderDumpFolder(s.options.shaderDump); !dumping) {
        std::cerr << exe << ": --dump-shaders: " << dumping.error() << "\n";
        return 2;
    }
    int code = run(s);
    // A shader that could not be written is a failed run: the folder would silently miss a variant.
    if (code == 0 && gl::shaderDumpFailures() > 0) code = 1;
    if (s.switchLesson != 0) {
        // The window is closed and the lesson released: the neighbour takes this process's place.
        if (auto next = neighbourLesson(s.exe, s.switchLesson)) {
            log::info("starting ", next->filename().string());
            Error failed = execLesson(*next, neighbourArguments(s.args, s.windowSize));
            log::error(failed.message);
            return 1;
        }
    }
    return code;
}

}  // namespace fx
