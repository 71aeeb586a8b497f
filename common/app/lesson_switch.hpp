#pragma once
// Moving between lessons in class while each lesson stays its own executable: Page Down / Page Up end
// this run and start the neighbouring lesson's executable (the next fxlab-NN-* beside this one, in
// number order) in its place, with the same window size and the flags that mean the same to every
// lesson. The process is replaced (exec; Windows, which has no exec, starts the neighbour and ends this
// one), so the teacher sees one window close and the next open at the same size; nothing of one
// lesson's GL state can leak into the next (lesson_switch_posix.cpp, lesson_switch_win.cpp).
//
// --all-steps runs this executable once per step the same way (as a child, waiting for each), so a
// step's captures are exactly what `--step K --capture DIR/step-K` gives.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "base/size2d.hpp"

namespace fx {

// Whether a file name is a lesson executable's: fxlab-NN-<name>.
bool isLessonExecutableName(const std::string& name);

// Whether `entry` is a program this system runs: an executable regular file (POSIX), a .exe (Windows).
bool isRunnableFile(const std::filesystem::directory_entry& entry);
// A program's name without the system's suffix: "fxlab-05-radial-blur" (Windows: of "...blur.exe").
std::string programName(const std::filesystem::path& executable);

// The lesson executables in `folder` (fxlab-NN-name, executable regular files), in number order.
std::vector<std::filesystem::path> lessonExecutables(const std::filesystem::path& folder);

// The executable `direction` (+1 next, -1 previous) from `current` ("fxlab-05-radial-blur") among
// `executables`; nothing at either end.
std::optional<std::filesystem::path> neighbourIn(const std::vector<std::filesystem::path>& executables,
                                                 const std::string& current, int direction);
// The same among the executables beside the running one.
std::optional<std::filesystem::path> neighbourLesson(const std::string& current, int direction);

// The command line for the neighbour: this run's flags without those that name something of this
// lesson (--step, --scene, --param, --preset, --inspect, --knob, --press), and --size set to the window's.
std::vector<std::string> neighbourArguments(const std::vector<std::string>& args, Size2D window);

// The command line for step `step` (1-based) of --all-steps: headless, without --all-steps, --capture,
// --report and --graph, with --step K --capture DIR/step-K --report DIR/step-K/report.json
// --graph DIR/step-K/graph.dot.
std::vector<std::string> stepCaptureArguments(const std::vector<std::string>& args,
                                              const std::filesystem::path& captureDir, int step);

// Replaces this process with `executable` run with `args`; returns only when that failed.
Error execLesson(const std::filesystem::path& executable, const std::vector<std::string>& args);
// Runs `executable` with `args` and waits: its exit code, or the reason it could not run. With an
// `output` file, the program's standard output and error go there instead of this process's.
Result<int> runAndWait(const std::filesystem::path& executable, const std::vector<std::string>& args,
                       const std::filesystem::path& output = {});

// This process's executable (/proc/self/exe; Windows: GetModuleFileNameW).
std::filesystem::path runningExecutable();

}  // namespace fx
