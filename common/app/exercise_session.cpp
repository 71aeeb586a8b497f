#include "app/exercise_session.hpp"
#include "app/exercise_rules.hpp"

#include "app/exercise_words.hpp"

#include <algorithm>
#include <cstdio>

#include "app/lesson_listing.hpp"
#include "base/file_io.hpp"
#include "base/log.hpp"
#include "base/words.hpp"

namespace fx {

namespace fs = std::filesystem;

namespace {

// `image` into `texture` (RGBA32F, made again when its size changes); an empty image frees it.
void upload(gl::Texture& texture, const FloatImage& image, const std::string& label) {
    if (image.empty()) {
        texture = {};
        return;
    }
    if (!texture || texture.width() != image.width || texture.height() != image.height)
        texture = gl::Texture::create2D(TextureFormat::RGBA32F, image.width, image.height, 1, label);
    static constexpr GLenum kFormats[4] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
    const GLenum format = kFormats[std::clamp(image.channels, 1, 4) - 1];
    // Rows bottom-up, as GL keeps them: the picture shows the probe's pixels upright.
    glTextureSubImage2D(texture.name(), 0, 0, 0, image.width, image.height, format, GL_FLOAT,
                        image.texels.data());
}

std::string shortNumber(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", double(value));
    return text;
}

}  // namespace

ExerciseView nextExerciseView(ExerciseView view) {
    switch (view) {
        case ExerciseView::Off:
            return ExerciseView::Student;
        case ExerciseView::Student:
            return ExerciseView::Reference;
        case ExerciseView::Reference:
            return ExerciseView::Difference;
        case ExerciseView::Difference:
            return ExerciseView::Off;
    }
    return ExerciseView::Off;
}

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
    if (Status localised = localiseExercise(*exercise, language); !localised) return Error{localised.error()};
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
    ExerciseVerdict verdict;
    if (auto notOwn = whyNotTheStudentsOwn(file_)) {
        verdict.error = verdict.message = *notOwn;
    } else {
        verdict = checkExercise(exercise_, file_);
    }
    if (verdict.passed != verdict_.passed || verdict.message != verdict_.message || revision_ == 0) {
        log::info("exercise ", exercise_.id(), ": ", verdict.passed ? "PASS" : "FAIL", ": ", verdict.message);
        if (!verdict.hint.empty()) log::info("exercise ", exercise_.id(), ": hint: ", verdict.hint);
        if (Status saved = recordProgress(studentRoot(), exercise_.id(), {verdict.passed, verdict.message});
            !saved)
            log::warning("exercise ", exercise_.id(), ": progress not saved: ", saved.error());
    }
    verdict_ = std::move(verdict);
    ++revision_;
    if (hasViews()) {
        upload(student_, verdict_.studentImage, cat("exercise.", exercise_.id(), ".student"));
        upload(reference_, verdict_.referenceImage, cat("exercise.", exercise_.id(), ".reference"));
    }
    return true;
}

PairDisplay ExerciseSession::display() const {
    PairDisplay display;
    display.scale = exercise_.display.scale;
    display.offset = exercise_.display.offset;
    display.keepAspect = true;
    return display;
}

std::string ExerciseSession::describeView(ExerciseView view) const {
    if (view == ExerciseView::Off) return {};
    const ExerciseDisplay& d = exercise_.display;
    const std::string offset = d.offset == 0.0f ? "" : cat(" + ", shortNumber(d.offset));
    const gl::Texture& shown = view == ExerciseView::Reference || !student_ ? reference_ : student_;
    std::string what;
    switch (view) {
        case ExerciseView::Student:
            what =
                student_ ? "YOURS: your file's result in the probe" : "YOURS: none, your file did not build";
            break;
        case ExerciseView::Reference:
            what = "REFERENCE: the right result";
            break;
        default:
            what = student_ ? cat("DIFFERENCE: |yours - reference| x ", shortNumber(d.scale), " x ",
                                  shortNumber(kDifferenceGain), ", black where they agree")
                            : "DIFFERENCE: none, your file did not build";
            break;
    }
    std::string colours = view == ExerciseView::Difference ? std::string()
                                                           : cat("; colour = value x ", shortNumber(d.scale),
                                                                 offset, " (red, green, blue)");
    return cat("exercise ", exercise_.id(), ", F3 view ", int(view), " of 3: ", what, ", ", shown.width(),
               "x", shown.height(), " (", exercise_.measures, "; the case the verdict is decided on)",
               colours, "; NaN and Inf magenta. ", verdictSummary(verdict_),
               ". F3: ", view == ExerciseView::Difference ? "back to the lesson's picture" : "the next view");
}

void ExerciseSession::releasePictures() {
    student_ = {};
    reference_ = {};
}

void ExerciseSession::annotate(std::vector<LessonStep>& steps, int& revision) const {
    if (step() < 0 || step() >= int(steps.size())) return;
    // The exercise first (it is what this run is for), then the step's own text.
    // Its heading, the verdict (what a glance at the projector needs), the hint, then its text.
    const std::size_t headingEnd = std::min(text_.find("\n\n"), text_.size());
    std::string text = cat(text_.substr(0, headingEnd), "\n\n**",
                           say(verdict_.passed ? "check.pass" : "check.fail"), "**: ", verdict_.message);
    if (!verdict_.hint.empty()) text += cat("\n\n", say("exercise.hint"), ": ", verdict_.hint);
    text += text_.substr(headingEnd);
    text += cat("\n\n", say("exercise.yourFile", {{"file", file_.string()}}));
    std::string& stepText = steps[std::size_t(step())].text;
    stepText = cat(text, "\n\n", stepText);
    revision += revision_;
}

}  // namespace fx
