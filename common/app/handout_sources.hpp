#pragma once
// What the handout takes from the lesson's files: lesson.md (and its translation) as a title, an
// introduction and the parts around the steps; the pictures its text shows, copied into figures/;
// and the bench's results (bench.json and its plots), where there are any.
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "app/handout_page.hpp"
#include "base/result.hpp"

namespace fx::handout {

// A lesson.md split as the page shows it; the steps' own text comes from LessonTextFiles, as the
// overlay reads it.
struct LessonText {
    std::string title, intro;
    std::vector<Part> before, after;  // the "## " parts before the first step, and the others
};
Result<LessonText> readLessonText(const std::filesystem::path& file);

// What a part is, whatever its language: "Checked exercise 1" of "Checked exercise 1: 平面反射" (a
// numbered section's word and number stay English in every language), else the whole heading.
std::string partKey(const std::string& heading);

// A translated part in place of the English-only part it translates, or after the others: each
// section is listed once (the Japanese page had "Checked exercise 1" twice, once marked English only).
void replaceOrAdd(std::vector<Part>& parts, const Part& translated);

// The pictures a lesson's texts show (their targets relative to the lesson's folder), copied into
// <handout>/figures/ once each; a picture that is not there is an error naming the text and the file.
class TextPictures {
public:
    TextPictures(std::filesystem::path lessonFolder, std::filesystem::path handout);
    Status add(const std::string& markdown, const std::filesystem::path& source);
    // The handout's file for each target added.
    PictureSource source() const;

private:
    std::filesystem::path lesson_, handout_;
    std::map<std::string, std::string> files_;
    std::set<std::string> used_;
};

// bench.json and bench-<knob>.png from `benchFolder` (./fxlab bench's output), the plots copied into
// `folder`; found stays false when there are none.
Result<BenchPart> readBench(const std::filesystem::path& benchFolder, const std::filesystem::path& folder);

}  // namespace fx::handout
