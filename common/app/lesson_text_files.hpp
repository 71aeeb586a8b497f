#pragma once
// A lesson's text as the overlay and --list-steps show it: read from the source tree
// (<root>/lessons/NN_name/lesson.md, and lesson.<language>.md for another language), matched with
// the step titles the lesson's code declares, and read again when a file changes (the runner polls,
// as it does for shaders). A file that is missing or does not match is an error naming the file and
// the step; the text read before stays, and with none the steps show their titles only. A step the
// translation lacks shows the English text with a note; so does a page beside the steps.
#include <filesystem>
#include <string>
#include <vector>

#include "base/lesson_text.hpp"
#include "base/result.hpp"

namespace fx {

// The languages a lesson's text can be shown in ("en" is lesson.md; "ja" is lesson.ja.md).
const std::vector<std::string>& lessonTextLanguages();

class LessonTextFiles {
public:
    LessonTextFiles(std::filesystem::path folder, std::vector<std::string> titles,
                    std::string language = "en");

    // Reads the files again if one of them changed (or appeared, or went) since the last read, and
    // logs a new error once. Returns true when it read them.
    bool reloadIfChanged();
    // The language shown; a language without its file shows English with a note on every step.
    const std::string& language() const { return language_; }
    Status setLanguage(const std::string& language);
    // The languages whose file exists for this lesson ("en" always).
    std::vector<std::string> available() const;

    // One per step: its title and text in the language shown, English where the translation lacks it.
    const std::vector<LessonStep>& steps() const { return shown_; }
    // The lesson's own pages (the sections beside the steps: the chapter's pitfalls, hard cases, its
    // other exercises), each with its heading as title, in the language shown; the nth page of the
    // translation stands for lesson.md's nth, and a page it lacks shows the English with a note.
    const std::vector<LessonStep>& pages() const { return shownPages_; }
    // What is wrong with the files now ("" when nothing is): shown in the overlay until fixed.
    const std::string& error() const { return error_; }
    // Grows whenever steps() changes, so the overlay knows when to look at the text again.
    int revision() const { return revision_; }
    // How many steps show the translation's text (0 for English).
    int translatedSteps() const { return translated_; }
    std::filesystem::path file(const std::string& language) const;

private:
    void read();
    void compose();

    std::filesystem::path folder_;
    std::vector<std::string> titles_;
    std::string language_;
    std::vector<std::filesystem::file_time_type> stamps_;  // lesson.md, then the translation
    bool readOnce_ = false;
    std::vector<std::string> english_;      // the last good lesson.md text, one per step
    std::vector<StepSection> translation_;  // the last good translation's section of each step
    std::vector<bool> hasTranslation_;      // per step: the translation has its section
    std::vector<LessonSection> englishPages_, translationPages_;
    std::vector<LessonStep> shownPages_;
    std::string englishError_, translationError_, error_;
    std::vector<LessonStep> shown_;
    int revision_ = 0;
    int translated_ = 0;
};

}  // namespace fx
