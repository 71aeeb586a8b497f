#pragma once
// The exercises (課題) and where a student's work on them lives. GL-free: the list, the start and the
// progress file have unit tests; app/exercise_check.hpp grades the work on a GL context.
//
//   exercises/LL-N/exercise.json    what the exercise is and how it is checked (docs/exercises.md)
//   exercises/LL-N/<file>           the starter: what the student copies and edits (never the answer)
//   exercises/LL-N/probe.frag       the shader the check renders, including the student's file
//   exercises/solutions/LL-N/       a solution and the typical wrong answers the hints are written for
//   $FXLAB_EXERCISES/LL-N/<file>    the student's copy (default ~/fxlab-exercises)
//   $FXLAB_EXERCISES/progress.json  the student's results, written by every check
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "base/size2d.hpp"

namespace fx {

// A uniform the check sets on the probe: numbers, or the case's size ("size": vec2(w, h)) or the
// centre of its middle pixel ("centre").
struct ExerciseUniform {
    std::string name;
    std::vector<float> values;
    std::string special;  // "", "size" or "centre"
};

// One rendering the student's result is compared on: a size (odd ones included) and the uniforms.
struct ExerciseCase {
    Size2D size;
    std::vector<ExerciseUniform> uniforms;
};

// A hint for a failing result: "nonFinite" when it has NaN or Inf, "matches" when it equals what a
// typical wrong answer (`file`) gives, "fails" for any other failure. A scene exercise's hints may also
// be "invalid" (the scene does not load), "noEmitter" or "overBudget".
struct ExerciseHint {
    std::string when;
    std::filesystem::path
        file;  // the typical wrong answer the hint is written for (absolute); "matches" needs one
    std::string text;
};

// How the probe's numbers show as colours in the lesson's exercise views (F3): each channel value v as
// v * scale + offset (red, green, blue; a probe writes tap offsets, pixels of blur, metres, colours).
// The difference view shows |student - reference| * scale times the view's gain.
struct ExerciseDisplay {
    float scale = 1.0f;
    float offset = 0.0f;
};

struct Exercise {
    // "probe": the student's shader is rendered by the probe and compared with the reference.
    // "scene": the student's file is a scene whose emitters are simulated (app/exercise_scene_check.hpp).
    std::string kind = "probe";
    int lesson = 0;  // 4
    int number = 0;  // 2
    std::string title;
    int step = 1;                     // the lesson's step (1-based) the exercise is shown at
    std::filesystem::path folder;     // exercises/04-2
    std::string file;                 // the student's file, a name in `folder`
    std::filesystem::path replaces;   // the file the student's stands in for (absolute)
    std::filesystem::path reference;  // the file whose result is right (absolute)
    std::filesystem::path probe;      // absolute
    std::vector<ExerciseCase> cases;
    std::string measure = "maxAbs";  // "maxAbs" or "rmse", per channel value
    double tolerance = 1e-5;
    std::string measures;  // what the probe's numbers are, for the message ("the tap offset of every pixel")
    std::vector<ExerciseHint> hints;
    ExerciseDisplay display;  // "probe" only
    // "scene" only: the most particles alive at once, and how long the emitters are simulated.
    int budget = 0;
    double seconds = 10.0;

    std::string id() const;  // "04-2"
};

// Reads `folder`/exercise.json. Errors name the file, the field and the reason.
Result<Exercise> loadExercise(const std::filesystem::path& folder);
// Every exercises/LL-N folder under `root` (projectRoot()/exercises by default), in lesson and number
// order. One bad exercise is an error naming it.
Result<std::vector<Exercise>> loadExercises(const std::filesystem::path& root);
std::filesystem::path exerciseRoot();
// "04-2", "4 2", "04 2": finds one; the error lists what exists.
Result<Exercise> findExercise(const std::vector<Exercise>& all, int lesson, int number);

// $FXLAB_EXERCISES, else ~/fxlab-exercises.
std::filesystem::path studentRoot();
std::filesystem::path studentFile(const Exercise& exercise, const std::filesystem::path& root);

// Copies the starter into root/LL-N/ unless the student's file is already there (their work is never
// overwritten; an existing non-regular file is refused). Returns the student's file.
Result<std::filesystem::path> startExercise(const Exercise& exercise, const std::filesystem::path& root);

// The last check of each exercise, by id.
struct ExerciseProgress {
    bool passed = false;
    std::string message;
};
using ProgressBook = std::map<std::string, ExerciseProgress>;
// root/progress.json; an absent file is an empty book, a malformed one an error naming it.
Result<ProgressBook> readProgress(const std::filesystem::path& root);
Status recordProgress(const std::filesystem::path& root, const std::string& id,
                      const ExerciseProgress& progress);

}  // namespace fx
