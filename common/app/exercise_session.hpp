#pragma once
// A lesson run with --exercise N: the exercise is a step of its lesson. The student's file stands in
// for the lesson's own (gl::ShaderSubstitute) for the whole run, so the lesson's passes build from it
// and the registry's reload picks up every save (the last good program kept, errors with file and
// line). Every save is checked again as `./fxlab check` checks it, and the step's text in the overlay
// gets the exercise's text (its "## Checked exercise N: title" section of lesson.md or lesson.ja.md)
// with the verdict: the measure, the threshold, pass or fail and the hint. After each check the probe's
// results of the case the verdict is decided on (the student's and the reference's) are textures that F3
// shows on the exercise's step (ExerciseView), so a student sees where their numbers differ.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/exercise_catalog.hpp"
#include "app/exercise_check.hpp"
#include "app/lesson.hpp"
#include "base/lesson_text.hpp"
#include "gl/shader_substitutes.hpp"
#include "gl/texture.hpp"
#include "ui/picture_view.hpp"

namespace fx {

// What F3 shows on a probe exercise's step: the lesson's picture (off), or the probe's results of the
// case the verdict is decided on: the student's, the reference's, their difference.
enum class ExerciseView { Off, Student, Reference, Difference };
ExerciseView nextExerciseView(ExerciseView view);  // off -> yours -> reference -> difference -> off

class ExerciseSession {
public:
    // Finds the lesson's exercise `number`, copies its starter to the student's folder when it is not
    // there yet, and sets the substitute. No GL needed.
    static Result<std::unique_ptr<ExerciseSession>> open(const LessonInfo& lesson, int number,
                                                         const std::string& language);

    int step() const { return exercise_.step - 1; }  // 0-based
    const ExerciseVerdict& verdict() const { return verdict_; }
    const std::filesystem::path& studentFile() const { return file_; }
    // A scene exercise: the student's file is a scene the lesson runs with (when it loads).
    bool studentFileIsAScene() const { return exercise_.kind == "scene"; }

    // Checks again (on the current GL context) when the student's file changed since the last check,
    // and says the verdict in the log when it changed; the verdict's pictures go to their textures.
    // True when it checked.
    bool recheckIfChanged();

    // A probe exercise has pictures to show (a scene exercise has none).
    bool hasViews() const { return exercise_.kind == "probe"; }
    // The probe's results (RGBA32F, labelled "exercise.LL-N.student" and ".reference"); the student's is
    // empty when their file did not build. Made or updated by each check.
    const gl::Texture& studentPicture() const { return student_; }
    const gl::Texture& referencePicture() const { return reference_; }
    // The exercise's colours (exercise.json's "display"), the pictures' aspect kept.
    PairDisplay display() const;
    // The lesson window's line for a view: what it shows, at what size, how numbers become colours, and
    // the verdict with its measure and threshold.
    std::string describeView(ExerciseView view) const;
    // Deletes the textures; the run calls it while its context is current (the session outlives it).
    void releasePictures();
    // The exercise's text and verdict after its step's text; `revision` grows when they change.
    void annotate(std::vector<LessonStep>& steps, int& revision) const;

private:
    ExerciseSession(Exercise exercise, std::filesystem::path file, std::string text);

    Exercise exercise_;
    std::filesystem::path file_;
    gl::ShaderSubstitute substitute_;
    std::string text_;
    std::filesystem::file_time_type stamp_{};
    bool checked_ = false;
    ExerciseVerdict verdict_;
    int revision_ = 0;
    gl::Texture student_, reference_;
};

// The text of "## Checked exercise N: title" in `markdown`, or an error naming `file`.
Result<std::string> exerciseSectionText(std::string_view markdown, const std::string& file, int number);

}  // namespace fx
