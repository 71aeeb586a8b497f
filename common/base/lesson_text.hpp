#pragma once
// A lesson's prose has one home: its lesson.md, one section per step, headed "## Step N: <title>".
// The lesson's code keeps the step list (the titles, since the steps drive the code); this reads a
// lesson.md (or a translation such as lesson.ja.md) and matches its step sections with that list.
// GL-free, so the unit tests, --list-steps and the overlay share it.
#include <string>
#include <string_view>
#include <vector>

#include "base/result.hpp"

namespace fx {

// A step as the overlay shows it: its title, its text (the markdown of its section) and, where the
// text is not in the language asked for, a short note saying so.
struct LessonStep {
    std::string title;
    std::string text;
    std::string note = {};
};

// One "## Step N: title" section of a lesson.md, as written.
struct StepSection {
    int number = 0;  // 1-based, as in the heading
    std::string title;
    std::string text;  // the lines up to the next heading of level 1 or 2, blank lines trimmed
    int line = 0;      // the heading's line, for messages
};

// Any section of a lesson.md: the text before the first heading (level 0, no heading), a "# title"
// (level 1) or a "## heading" (level 2) with the lines up to the next such heading ("### x" stays
// inside; headings inside ``` code blocks are not headings). The handout shows the whole file.
struct LessonSection {
    int level = 0;
    std::string heading;  // without the #s
    std::string text;     // blank lines at either end trimmed
    int line = 0;         // the heading's line (1 for the text before any heading)
};
std::vector<LessonSection> parseLessonSections(std::string_view markdown);
// Whether a section is a step's ("## Step ..."): such a heading must be "## Step N: title". Another
// `word` asks the same of another kind of numbered section ("Checked exercise"). A translation heads
// them in its own words, taken alike in any file: "## ステップ N: title", "## 確認課題 N: title".
bool isStepSection(const LessonSection& section, std::string_view word = "Step");

// The sections beside the steps, which are the lesson's own pages after them in the overlay and
// parts of the handout: every "## " section of a lesson.md that is neither a step's nor a checked
// exercise's (those are shown in their own places), in the order written. A translation gives its
// pages in the same order as lesson.md, so the nth page of one is the nth of the other.
std::vector<LessonSection> lessonPages(std::string_view markdown);

// The step sections of a markdown file, in the order written, with nothing checked against a
// lesson. Other sections ("## The frame") are prose around the steps and are skipped; headings inside
// ``` code blocks are not headings. A heading that starts with "## Step" but is not "## Step N: title"
// is an error naming the file and line. `word` picks another kind of numbered section: "Checked
// exercise" reads the "## Checked exercise N: title" sections (app/exercise_session.hpp), which the
// steps skip.
Result<std::vector<StepSection>> parseStepSections(std::string_view markdown, const std::string& file,
                                                   std::string_view word = "Step");

// The lesson's own text (lesson.md): exactly one section per step, in order, each with text, each
// heading's title the same as the lesson's title for that step. Gives the text of every step.
Result<std::vector<std::string>> matchLessonText(const std::vector<StepSection>& sections,
                                                 const std::vector<std::string>& titles,
                                                 const std::string& file);

// A translation (lesson.ja.md): sections in order, no step twice, none the lesson lacks, each with
// text; a step may be missing (it falls back to English). Titles are translated, so they are not
// compared. Gives one entry per step, nullptr where the translation has no section.
Result<std::vector<const StepSection*>> matchTranslation(const std::vector<StepSection>& sections,
                                                         std::size_t stepCount, const std::string& file);

}  // namespace fx
