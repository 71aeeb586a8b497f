#include "app/exercise_session.hpp"

#include <algorithm>

#include "app/lesson_listing.hpp"
#include "base/file_io.hpp"
#include "base/log.hpp"

namespace fx {

namespace fs = std::filesystem;

Result<std::string> exerciseSectionText(std::string_view markdown, const std::string& file, int number) {
    auto sections = parseStepSections(markdown, file, "Checked exercise");
    if (!sections) return Error{sections.error()};
    for (const StepSection& s : *sections) {
        if (s.number == number) return cat("### Checked exercise ", number, ": ", s.title, "\n\n", s.text);
    }
    return Error{cat(file, ": no section \"## Checked exercise ", number, ": title\"")};
}

Result<std::unique_ptr<ExerciseSession>> ExerciseSession::open(const LessonInfo& lesson, int number,
                                                               const std::string& language) {
    auto all = loadExercises(exerciseRoot());
    if (!all) return Error{all.error()};
    auto exercise = findExercise(*all, lesson.number, number);
    if (!exercise) return Error{exercise.error()};
    auto file = startExercise(*exercise, studentRoot());
    if (!file) return Error{file.error()};
    // The translation where it has the section, else the English.
    std::string text;
    for (const std::string& name : {cat("lesson.", language, ".md"), std::string("lesson.md")}) {
        if (name == "lesson.en.md") continue;
        const fs::path path = lessonSourceFolder(lesson) / name;
        auto markdown = readTextFile(path);
        if (!markdown) continue;
        auto section = exerciseSectionText(*markdown, path.string(), number);
        if (section) {
            text = *section;
            break;
        }
        if (name == "lesson.md") return Error{section.error()};
    }
    return std::unique_ptr<ExerciseSession>(
        new ExerciseSession(std::move(*exercise), *file, std::move(text)));
}

ExerciseSession::ExerciseSession(Exercise exercise, fs::path file, std::string text)
    : exercise_(std::move(exercise)),
      file_(std::move(file)),
      substitute_(exercise_.replaces, file_),
      text_(std::move(text)) {
    log::info("exercise ", exercise_.id(), ": your file is ", file_.string(), " (it stands in for ",
              exercise_.replaces.filename().string(), "; every save is checked)");
}

bool ExerciseSession::recheckIfChanged() {
    std::error_code ec;
    const auto stamp = fs::last_write_time(file_, ec);
    if (checked_ && !ec && stamp == stamp_) return false;
    checked_ = true;
    stamp_ = stamp;
    ExerciseVerdict verdict = checkExercise(exercise_, file_);
    if (verdict.passed != verdict_.passed || verdict.message != verdict_.message || revision_ == 0) {
        log::info("exercise ", exercise_.id(), ": ", verdict.passed ? "PASS" : "FAIL", ": ", verdict.message);
        if (!verdict.hint.empty()) log::info("exercise ", exercise_.id(), ": hint: ", verdict.hint);
        if (Status saved = recordProgress(studentRoot(), exercise_.id(), {verdict.passed, verdict.message});
            !saved)
            log::warning("exercise ", exercise_.id(), ": progress not saved: ", saved.error());
    }
    verdict_ = std::move(verdict);
    ++revision_;
    return true;
}

void ExerciseSession::annotate(std::vector<LessonStep>& steps, int& revision) const {
    if (step() < 0 || step() >= int(steps.size())) return;
    // The exercise first (it is what this run is for), then the step's own text.
    // Its heading, the verdict (what a glance at the projector needs), the hint, then its text.
    const std::size_t headingEnd = std::min(text_.find("\n\n"), text_.size());
    std::string text = cat(text_.substr(0, headingEnd), "\n\n",
                           verdict_.passed ? "**PASS**: " : "**FAIL**: ", verdict_.message);
    if (!verdict_.hint.empty()) text += cat("\n\nHint: ", verdict_.hint);
    text += text_.substr(headingEnd);
    text += cat("\n\nYour file: `", file_.string(), "` (every save rebuilds the lesson and checks it again)");
    std::string& stepText = steps[std::size_t(step())].text;
    stepText = cat(text, "\n\n", stepText);
    revision += revision_;
}

}  // namespace fx
