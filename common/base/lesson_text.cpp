#include "base/lesson_text.hpp"

#include <charconv>

#include "base/log.hpp"

namespace fx {
namespace {

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

bool startsWith(std::string_view s, std::string_view prefix) {
    return s.substr(0, prefix.size()) == prefix;
}

// "# x" or "## x": the headings that end a step's section ("### x" stays inside it).
bool isSectionBoundary(std::string_view line) {
    return startsWith(line, "# ") || startsWith(line, "## ");
}

std::string joinedText(const std::vector<std::string_view>& lines) {
    std::size_t first = 0, last = lines.size();
    while (first < last && trimmed(lines[first]).empty()) ++first;
    while (last > first && trimmed(lines[last - 1]).empty()) --last;
    std::string text;
    for (std::size_t i = first; i < last; ++i) {
        if (i > first) text += '\n';
        std::string_view line = lines[i];
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        text += line;
    }
    return text;
}

// The heading's word in the lesson's other language: a translation heads its sections in its own
// words ("## ステップ 1: ...", "## 確認課題 1: ..."), and either word starts the same kind of section.
std::string_view translatedWord(std::string_view word) {
    if (word == "Step") return "ステップ";
    if (word == "Checked exercise") return "確認課題";
    return {};
}

// The word the heading starts with, of the two that name `word`'s kind of section ("" for neither).
std::string_view headingWord(const LessonSection& section, std::string_view word) {
    if (section.level != 2) return {};
    if (startsWith(section.heading, word)) return word;
    const std::string_view translated = translatedWord(word);
    if (!translated.empty() && startsWith(section.heading, translated)) return translated;
    return {};
}

}  // namespace

std::vector<LessonSection> parseLessonSections(std::string_view markdown) {
    std::vector<LessonSection> sections{{0, {}, {}, 1}};
    std::vector<std::string_view> body;
    bool inCode = false;
    int lineNumber = 0;
    std::size_t start = 0;
    while (start <= markdown.size()) {
        std::size_t end = markdown.find('\n', start);
        if (end == std::string_view::npos) end = markdown.size();
        std::string_view line = markdown.substr(start, end - start);
        start = end + 1;
        ++lineNumber;
        if (startsWith(trimmed(line), "```")) inCode = !inCode;
        if (inCode || !isSectionBoundary(line)) {
            body.push_back(line);
        } else {
            sections.back().text = joinedText(body);
            body.clear();
            const int level = startsWith(line, "## ") ? 2 : 1;
            sections.push_back(
                {level, std::string(trimmed(line.substr(line.find(' ') + 1))), {}, lineNumber});
        }
        if (end == markdown.size()) break;
    }
    sections.back().text = joinedText(body);
    if (sections.front().text.empty()) sections.erase(sections.begin());
    return sections;
}

bool isStepSection(const LessonSection& section, std::string_view word) {
    return !headingWord(section, word).empty();
}

std::vector<LessonSection> lessonPages(std::string_view markdown) {
    std::vector<LessonSection> pages;
    for (LessonSection& section : parseLessonSections(markdown)) {
        if (section.level == 2 && !isStepSection(section) && !isStepSection(section, "Checked exercise"))
            pages.push_back(std::move(section));
    }
    return pages;
}

Result<std::vector<StepSection>> parseStepSections(std::string_view markdown, const std::string& file,
                                                   std::string_view word) {
    std::vector<StepSection> steps;
    for (const LessonSection& section : parseLessonSections(markdown)) {
        const std::string_view heading = section.heading;
        const std::string_view written = headingWord(section, word);
        if (written.empty()) continue;
        // "## Step N: title" (or another word: "## Checked exercise N: title"; or the translation's)
        std::string_view rest = heading.substr(written.size());
        std::size_t colon = rest.find(':');
        std::string_view number =
            colon == std::string_view::npos ? std::string_view{} : trimmed(rest.substr(0, colon));
        int n = 0;
        auto [ptr, ec] = std::from_chars(number.data(), number.data() + number.size(), n);
        std::string_view title =
            colon == std::string_view::npos ? std::string_view{} : trimmed(rest.substr(colon + 1));
        if (rest.empty() || rest.front() != ' ' || number.empty() || ec != std::errc() ||
            ptr != number.data() + number.size() || n < 1 || title.empty()) {
            const std::string kind = word == "Step" ? "step" : cat("\"", word, "\"");
            return Error{cat(file, ":", section.line, ": \"## ", heading, "\" is not a ", kind,
                             " heading; write \"## ", written, " N: title\" (N from 1)")};
        }
        steps.push_back({n, std::string(title), section.text, section.line});
    }
    return steps;
}

Result<std::vector<std::string>> matchLessonText(const std::vector<StepSection>& sections,
                                                 const std::vector<std::string>& titles,
                                                 const std::string& file) {
    std::vector<std::string> texts;
    for (std::size_t i = 0; i < sections.size(); ++i) {
        const StepSection& s = sections[i];
        const int expected = int(i) + 1;
        if (s.number > int(titles.size())) {
            return Error{cat(file, ":", s.line, ": step ", s.number, ": the lesson has ", titles.size(),
                             " steps; remove this section or add the step to the lesson's code")};
        }
        if (s.number < expected) {
            return Error{cat(file, ":", s.line, ": step ", s.number, " comes again after step ", expected - 1,
                             "; each step has one section, in order")};
        }
        if (s.number > expected) {
            return Error{cat(file, ": step ", expected, " (\"", titles[i], "\") has no section; \"## Step ",
                             s.number, "\" at line ", s.line, " comes first")};
        }
        if (s.title != titles[i]) {
            return Error{cat(file, ":", s.line, ": step ", s.number, ": the heading's title \"", s.title,
                             "\" is not the lesson's \"", titles[i], "\"")};
        }
        if (s.text.empty()) return Error{cat(file, ":", s.line, ": step ", s.number, " has no text")};
        texts.push_back(s.text);
    }
    if (sections.size() < titles.size()) {
        std::size_t missing = sections.size();
        return Error{cat(file, ": step ", missing + 1, " (\"", titles[missing],
                         "\") has no section; write \"## Step ", missing + 1, ": ", titles[missing],
                         "\" and its text")};
    }
    return texts;
}

Result<std::vector<const StepSection*>> matchTranslation(const std::vector<StepSection>& sections,
                                                         std::size_t stepCount, const std::string& file) {
    std::vector<const StepSection*> byStep(stepCount, nullptr);
    int previous = 0;
    for (const StepSection& s : sections) {
        if (s.number > int(stepCount)) {
            return Error{
                cat(file, ":", s.line, ": step ", s.number, ": the lesson has ", stepCount, " steps")};
        }
        if (s.number <= previous) {
            return Error{cat(file, ":", s.line, ": step ", s.number, " comes after step ", previous,
                             "; each step has at most one section, in order")};
        }
        if (s.text.empty()) return Error{cat(file, ":", s.line, ": step ", s.number, " has no text")};
        byStep[std::size_t(s.number - 1)] = &s;
        previous = s.number;
    }
    return byStep;
}

}  // namespace fx
