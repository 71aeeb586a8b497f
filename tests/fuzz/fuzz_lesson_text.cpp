// Lesson text (base/lesson_text.hpp, base/markdown_text.hpp) on any bytes: the step sections, matched
// as a lesson.md and as a translation, and each section's markdown as the overlay lays it out.
#include "base/lesson_text.hpp"
#include "base/line_break.hpp"
#include "base/markdown_text.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // Lesson 01's titles, so that its lesson.md (a seed) matches and the fuzzer starts from a whole lesson.
    static const std::vector<std::string> titles = {
        "Copy-pasted programs", "A program object with error checks", "Look uniform locations up once",
        "Parentheses in the skinning product", "Reload while running"};
    auto sections = fx::parseStepSections(fuzz::text(data, size), "lesson.md");
    if (!sections) return 0;
    (void)fx::matchLessonText(*sections, titles, "lesson.md");
    (void)fx::matchTranslation(*sections, titles.size(), "lesson.ja.md");
    for (const fx::StepSection& section : *sections) {
        for (const auto& block : fx::markdown::parseBlocks(section.text)) (void)block;
        for (const auto& span : fx::markdown::parseSpans(section.text)) (void)span;
        for (auto piece : fx::lineBreakPieces(section.text)) (void)piece;
    }
    return 0;
}
