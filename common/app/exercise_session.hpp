#pragma once
// A lesson run with --exercise N: the exercise is a step of its lesson. The student's file stands in
// for the lesson's own (gl::ShaderSubstitute) for the whole run, so the lesson's passes build from it
// and the registry's reload picks up every save (the last good program kept, errors with file and
// line). Every save is checked again as `./fxlab check` checks it, and the step's text in the overlay
// gets the exercise's text (its "## Checked exercise N: title" section of lesson.md or lesson.ja.md)
// with the verdict: the measure, the threshold, pass or fail and the hint.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/exercise_catalog.hpp"
#include "app/exercise_check.hpp"
#include "app/lesson.hpp"
#include "base/lesson_text.hpp"
#include "gl/shader_substitutes.hpp"

namespace fx {

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
    // and says the verdict in the log when it changed. True when it checked.
    bool recheckIfChanged();
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
};

// The text of "## Checked exercise N: title" in `markdown`, or an error naming `file`.
Result<std::string> exerciseSectionText(std::string_view markdown, const std::string& file, int number);

}  // namespace fx
