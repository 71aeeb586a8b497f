#include "base/words.hpp"

#include <algorithm>

#include "base/file_io.hpp"
#include "base/log.hpp"
#include "base/message_text.hpp"
#include "base/paths.hpp"

namespace fx {

namespace {

constexpr std::string_view kSeparator = " = ";

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

// A "{" without its "}", or a "}" without its "{": the text would show braces the writer did not mean.
bool bracesMatch(std::string_view text) {
    bool open = false;
    for (char c : text) {
        if (c == '{') {
            if (open) return false;
            open = true;
        } else if (c == '}') {
            if (!open) return false;
            open = false;
        }
    }
    return !open;
}

}  // namespace

std::set<std::string> WordsFile::placeholders(std::string_view text) {
    std::set<std::string> names;
    for (std::size_t open = text.find('{'); open != std::string_view::npos; open = text.find('{', open + 1)) {
        std::size_t close = text.find('}', open);
        if (close == std::string_view::npos) break;
        names.emplace(text.substr(open + 1, close - open - 1));
    }
    return names;
}

Result<WordsFile> parseWords(std::string_view text, std::string_view fileName) {
    WordsFile file;
    int lineNumber = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = trimmed(text.substr(start, end - start));
        ++lineNumber;
        start = end + 1;
        if (line.empty() || line.front() == '#') continue;
        const std::string where = cat(fileName, ":", lineNumber, ": ");
        std::size_t split = line.find(kSeparator);
        if (split == std::string_view::npos)
            return Error{where + "expected 'key = text', got: " + excerpt(line)};
        std::string_view key = trimmed(line.substr(0, split));
        std::string_view value = trimmed(line.substr(split + kSeparator.size()));
        if (key.empty() || key.find_first_of(" \t{}") != std::string_view::npos)
            return Error{where + "the key '" + excerpt(key) + "' is empty or has a space or a brace"};
        if (value.empty()) return Error{where + "the key '" + std::string(key) + "' has no text"};
        if (!bracesMatch(value))
            return Error{where + "the text of '" + std::string(key) + "' has a '{' or '}' without its pair"};
        if (!file.entries.emplace(std::string(key), std::string(value)).second)
            return Error{where + "the key '" + std::string(key) + "' is given twice"};
    }
    return file;
}

Result<WordsFile> readWords(const std::filesystem::path& file) {
    auto text = readFile(file, file_limits::preset);
    if (!text) return Error{text.error()};
    return parseWords(*text, file.string());
}

std::string fillWords(std::string_view text, const WordArgs& args) {
    std::string out;
    out.reserve(text.size());
    std::size_t at = 0;
    while (at < text.size()) {
        std::size_t open = text.find('{', at);
        if (open == std::string_view::npos) break;
        std::size_t close = text.find('}', open);
        if (close == std::string_view::npos) break;
        out.append(text.substr(at, open - at));
        std::string_view name = text.substr(open + 1, close - open - 1);
        auto arg = std::find_if(args.begin(), args.end(), [&](const WordArg& a) { return a.name == name; });
        if (arg != args.end())
            out += arg->value;
        else
            out.append(text.substr(open, close - open + 1));
        at = close + 1;
    }
    out.append(text.substr(at));
    return out;
}

const std::vector<std::string>& wordLanguages() {
    static const std::vector<std::string> languages{"en", "ja"};
    return languages;
}

std::filesystem::path appWordsFile(const std::string& language) {
    return projectRoot() / "common" / "words" / ("words." + language);
}

std::filesystem::path lessonWordsFile(const std::filesystem::path& lessonFolder,
                                      const std::string& language) {
    return lessonFolder / ("words." + language);
}

Result<Words> Words::loadApp(const std::string& language) {
    auto app = readWords(appWordsFile(language));
    if (!app) return Error{app.error()};
    Words w;
    w.language_ = language;
    w.app_ = std::move(*app);
    return w;
}

Result<Words> Words::load(const std::filesystem::path& lessonFolder, const std::string& language) {
    auto w = loadApp(language);
    if (!w) return w;
    // A lesson that shows no words of its own (README's smallest lesson, the tests' probe lessons) has
    // no words file; a key it does show without one is still a missing word, reported by the run.
    const std::filesystem::path file = lessonWordsFile(lessonFolder, language);
    std::error_code ec;
    if (std::filesystem::symlink_status(file, ec).type() == std::filesystem::file_type::not_found) return w;
    auto lesson = readWords(file);
    if (!lesson) return Error{lesson.error()};
    w->lesson_ = std::move(*lesson);
    return w;
}

std::vector<std::string_view> Words::allTexts() const {
    std::vector<std::string_view> texts;
    for (const WordsFile* f : {&lesson_, &app_}) {
        for (const auto& [key, text] : f->entries) texts.push_back(text);
    }
    return texts;
}

bool Words::has(std::string_view key) const {
    return lesson_.entries.count(key) > 0 || app_.entries.count(key) > 0;
}

namespace {
std::vector<std::string>& missing() {
    static std::vector<std::string> keys;
    return keys;
}
}  // namespace

std::string Words::text(std::string_view key, const WordArgs& args) const {
    if (auto it = lesson_.entries.find(key); it != lesson_.entries.end()) return fillWords(it->second, args);
    if (auto it = app_.entries.find(key); it != app_.entries.end()) return fillWords(it->second, args);
    std::vector<std::string>& keys = missing();
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.emplace_back(key);
    return cat("[", key, "]");
}

std::string Words::textOr(std::string_view key, std::string_view fallback, const WordArgs& args) const {
    return has(key) ? text(key, args) : fillWords(fallback, args);
}

namespace {
// Until a run chooses its words, the app's English (what a tool or a test that chooses none shows).
Words& current() {
    static Words w = [] {
        auto english = Words::loadApp("en");
        if (!english) log::error(english.error());
        return english ? std::move(*english) : Words{};
    }();
    return w;
}
}  // namespace

const Words& words() {
    return current();
}

void useWords(Words w) {
    current() = std::move(w);
}

std::string say(std::string_view key, const WordArgs& args) {
    return words().text(key, args);
}

const std::vector<std::string>& missingWords() {
    return missing();
}

std::string stepsText(const std::vector<int>& steps) {
    std::vector<int> s = steps;
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end()), s.end());
    if (s.empty()) return {};
    if (s.size() == 1) return say("steps.one", {{"n", cat(s[0] + 1)}});
    bool contiguous = s.back() - s.front() + 1 == int(s.size());
    if (s.size() == 2) return say("steps.two", {{"a", cat(s[0] + 1)}, {"b", cat(s[1] + 1)}});
    if (contiguous) return say("steps.range", {{"a", cat(s.front() + 1)}, {"b", cat(s.back() + 1)}});
    // A words file trims its texts, so the space after an English comma is added here.
    std::string join = say("steps.join");
    if (join == ",") join += ' ';
    std::string list;
    for (std::size_t i = 0; i + 1 < s.size(); ++i) list += (i ? join : "") + cat(s[i] + 1);
    return say("steps.list", {{"list", list}, {"b", cat(s.back() + 1)}});
}

}  // namespace fx
