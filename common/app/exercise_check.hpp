#pragma once
// Grades a student's file: the exercise's probe shader is rendered with the student's file in place
// of the one it replaces and again with the reference, at every case's size (odd ones included), and
// the two are compared as floats. A verdict says what it measured against what threshold, counts NaN
// and Inf, names compile errors with the student's file and line, and gives the hint written for the
// mistake it matches (a typical wrong answer rendered the same way).
//
// checkExercise needs a current GL context and trusts the shader to finish; checkExerciseGuarded runs
// it in a child process with its own headless context and a watchdog, so a shader that loops forever
// is a failed check, not a hung grader.
#include <cstdint>
#include <filesystem>
#include <string>

#include "app/exercise_catalog.hpp"
#include "image/image.hpp"

namespace fx {

struct ExerciseVerdict {
    bool passed = false;
    std::string measure;    // "maxAbs", "rmse"
    double measured = 0.0;  // over all cases, the worst; +inf when a value is NaN or Inf
    double tolerance = 0.0;
    std::int64_t nonFiniteTexels = 0;
    std::string message;  // one line: what was measured against what, or why nothing could be
    std::string hint;     // for a failure: the hint for the mistake it looks like
    std::string error;    // a compile or link error (file and line), a missing file, a watchdog
    // The probe's results (RGBA floats, rows bottom-up) in the case the verdict is decided on: the worst,
    // so the lesson's exercise views (F3) show what the measure saw. When the student's file did not
    // build, the reference's of the first case alone. Kept in this process only (not in the JSON).
    FloatImage studentImage;
    FloatImage referenceImage;
};

ExerciseVerdict checkExercise(const Exercise& exercise, const std::filesystem::path& studentFile);

// "FAIL: max |difference| inf, needs <= 1e-05": pass or fail with the measure and its threshold.
std::string verdictSummary(const ExerciseVerdict& verdict);

// checkExercise in a child process that gets `seconds` to finish.
// The child's work of checkExerciseGuarded, by name (app/child_watchdog.hpp); a program that grades
// calls registerExerciseCheckWork, then runChildWorkIfAsked, first thing in main().
inline constexpr const char* kExerciseCheckWork = "check-exercise";
void registerExerciseCheckWork();
ExerciseVerdict checkExerciseGuarded(const Exercise& exercise, const std::filesystem::path& studentFile,
                                     double seconds);

// The verdict as JSON (the child's answer, `check --json`) and back.
std::string verdictJson(const ExerciseVerdict& verdict);
Result<ExerciseVerdict> verdictFromJson(const std::string& text);

}  // namespace fx
