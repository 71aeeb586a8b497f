#pragma once
// The words a student reads, kept out of the C++: the app's own in common/words/words.<language>, a
// lesson's in lessons/NN_name/words.<language>, looked up by key. A words file is plain text, one entry
// a line:
//
//   # a comment
//   fact.levels = levels (of {asked} asked for)
//
// The key is everything before the first " = ", the text everything after it; "{name}" in the text is
// replaced by the value the code passes under that name. A key a file gives twice, a line without
// " = ", an empty text or an unclosed "{" is an error naming the file and the line.
//
// The run's words (words()) are those of the language shown: the lesson's, then the app's. A key that
// neither has is a mistake the unit tests find (tests/unit/base/test_lesson_words.cpp); at run time it
// shows as the key in brackets and is remembered (missingWords()), so a run can report it.
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.hpp"

namespace fx {

// A value for "{name}" in a text.
struct WordArg {
    std::string name;
    std::string value;
};
using WordArgs = std::vector<WordArg>;

// One words file, read.
struct WordsFile {
    std::map<std::string, std::string, std::less<>> entries;
    // The "{name}"s each entry's text takes, for comparing two languages' files.
    static std::set<std::string> placeholders(std::string_view text);
};

// Parses a words file's text; `fileName` names it in errors ("lessons/06_bloom/words.ja:12: ...").
Result<WordsFile> parseWords(std::string_view text, std::string_view fileName);
Result<WordsFile> readWords(const std::filesystem::path& file);

// `text` with every "{name}" replaced by its value; a name without a value stays as it is.
std::string fillWords(std::string_view text, const WordArgs& args);

// The languages the words come in: "en", "ja" (the same as the lessons' text).
const std::vector<std::string>& wordLanguages();
// The app's words file and a lesson's (folder: lessons/NN_name) for a language.
std::filesystem::path appWordsFile(const std::string& language);
std::filesystem::path lessonWordsFile(const std::filesystem::path& lessonFolder, const std::string& language);

class Words {
public:
    Words() = default;
    // The lesson's words, then the app's, for `language`. An error names the file.
    static Result<Words> load(const std::filesystem::path& lessonFolder, const std::string& language);
    // The app's words only (for what runs without a lesson: ./fxlab check).
    static Result<Words> loadApp(const std::string& language);

    const std::string& language() const { return language_; }
    bool has(std::string_view key) const;
    // The text of `key`, filled; "[key]" when neither file has it (remembered in missingWords()).
    std::string text(std::string_view key, const WordArgs& args = {}) const;
    // The text of `key` if there is one, else `fallback`.
    std::string textOr(std::string_view key, std::string_view fallback, const WordArgs& args = {}) const;
    // Every text of both files, unfilled: the overlay's font atlas needs their glyphs.
    std::vector<std::string_view> allTexts() const;

private:
    std::string language_ = "en";
    WordsFile lesson_, app_;
};

// The run's words, in the language shown (the app's English until useWords()).
const Words& words();
void useWords(Words w);
// Shorthand for words().text(key, args).
std::string say(std::string_view key, const WordArgs& args = {});
// The keys asked for that no file had, in the order first asked.
const std::vector<std::string>& missingWords();

// "Step 5", "Steps 4 and 5", "Steps 3 to 6", "Steps 1, 3 and 5" (0-based in, 1-based shown), in the
// run's words ("steps.one", "steps.two", "steps.range", "steps.list", "steps.join").
std::string stepsText(const std::vector<int>& steps);

}  // namespace fx
