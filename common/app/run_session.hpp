#pragma once
// One run of a lesson, as the runner's pieces share it: the lesson, what the command line asked,
// the parameters, the scene, and where the run is (step, status line).
#include <filesystem>
#include <memory>
#include <string>

#include "app/lesson.hpp"
#include "app/run_options.hpp"
#include "app/ui_settings.hpp"

namespace fx {

class ExerciseSession;
class RenderDocSession;

struct RunSession {
    std::unique_ptr<Lesson> lesson;  // released while the context is current (LessonRelease)
    std::string exe;                 // "fxlab-05-radial-blur"
    RunOptions options;
    ParamSet params;  // points into the lesson: used only while it lives
    Scene scene;
    int step = 0;  // 0-based
    std::string status;
    std::vector<std::string> args;  // the command line after the program's name (for the next lesson)
    // In a window: the text scale, window size and layout the teacher left (app/ui_settings.hpp).
    UiSettings ui;
    // Set by Page Down / Page Up: +1 or -1 starts the neighbouring lesson when this run ends, in a
    // window of windowSize (app/lesson_switch.hpp).
    int switchLesson = 0;
    Size2D windowSize;
    // --exercise N: the student's file in the lesson, checked at every save (app/exercise_session.hpp).
    std::shared_ptr<ExerciseSession> exercise;
    // --renderdoc FILE.rdc: the frames RenderDoc captures (app/renderdoc_session.hpp).
    std::shared_ptr<RenderDocSession> renderdoc;
};

// Where a run draws and what it leaves behind, decided from the options and whether a display exists.
struct RunPlan {
    bool headless = false;
    std::filesystem::path captureDir;
    std::filesystem::path reportFile;
    int frames = 0;  // 0: until the window closes
};

RunPlan planRun(const RunOptions& options, const std::string& exe);

// Destroys the lesson (and with it every GL object it owns) when the run ends, however it ends.
// Declare it right after the context: what is declared later (renderer, overlay) goes first, then
// the lesson, then the context, so every GL object is deleted while its context is current.
class LessonRelease {
public:
    explicit LessonRelease(RunSession& session) : session_(session) {}
    ~LessonRelease() { session_.lesson.reset(); }
    LessonRelease(const LessonRelease&) = delete;
    LessonRelease& operator=(const LessonRelease&) = delete;

private:
    RunSession& session_;
};

}  // namespace fx
