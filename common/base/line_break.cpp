#include "base/line_break.hpp"

#include <unicode/brkiter.h>
#include <unicode/locid.h>
#include <unicode/utext.h>

#include <array>
#include <cctype>
#include <memory>

namespace fx {
namespace {

// ICU's line iterator for Japanese with its strict rules (no line starts with a small kana or the
// prolonged sound mark; they hold for English text too). Made once, cloned per thread: making one
// reads the rules (milliseconds), and an iterator is not shared between threads.
icu::BreakIterator* lineIterator() {
    static std::unique_ptr<icu::BreakIterator> prototype = [] {
        UErrorCode status = U_ZERO_ERROR;
        std::unique_ptr<icu::BreakIterator> it(
            icu::BreakIterator::createLineInstance(icu::Locale("ja@lb=strict"), status));
        return U_SUCCESS(status) ? std::move(it) : nullptr;
    }();
    thread_local std::unique_ptr<icu::BreakIterator> mine(prototype ? prototype->clone() : nullptr);
    return mine.get();
}

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

std::string_view withoutTrailingSpaces(std::string_view s) {
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

// "16 " before "ms", "900 " before "個": a number (its last word all digits, with a decimal point or
// a sign) and a space, before a word that is not a number.
bool isNumberBeforeItsUnit(std::string_view piece, std::string_view next) {
    const std::string_view word = withoutTrailingSpaces(piece);
    if (word.size() == piece.size() || word.empty() || next.empty()) return false;
    if (!isDigit(word.back())) return false;
    std::size_t start = word.size();
    while (start > 0 && (isDigit(word[start - 1]) || word[start - 1] == '.' || word[start - 1] == ','))
        --start;
    if (start > 0 && std::isalpha(static_cast<unsigned char>(word[start - 1]))) return false;  // "RGBA8 x"
    const unsigned char first = static_cast<unsigned char>(next.front());
    if (isDigit(char(first)) || first == '(' || first == '-' || first == '+' || first == '=' || first == '*')
        return false;
    // Japanese after a number is its counter or particle ("900 個", "8 に"); Latin, one of the units
    // the lessons write.
    if (first >= 0x80) return true;
    static constexpr std::array<std::string_view, 20> units = {"ms", "s",  "ns",  "us",  "px",  "m",   "mm",
                                                               "cm", "%",  "x",   "MiB", "KiB", "GiB", "MB",
                                                               "KB", "GB", "fps", "Hz",  "bit", "bits"};
    std::string_view unit = withoutTrailingSpaces(next);
    while (!unit.empty() && std::ispunct(static_cast<unsigned char>(unit.back())) && unit.back() != '%')
        unit.remove_suffix(1);  // "ms," "ms)"
    for (std::string_view u : units)
        if (unit == u) return true;
    return false;
}

// "1/" before "F": a fraction or a ratio written with a slash stays whole ("1/F", "1/P", "a/b");
// a slash between words with spaces around it still lets the line break.
bool isInsideAFraction(std::string_view piece, std::string_view next) {
    if (piece.size() < 2 || piece.back() != '/' || next.empty()) return false;
    const auto alnum = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; };
    return alnum(piece[piece.size() - 2]) && alnum(next.front());
}

// Characters in a piece, counted as code points.
std::size_t characters(std::string_view s) {
    std::size_t n = 0;
    for (char c : s) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    return n;
}

bool isLone(std::string_view line) {
    line = withoutTrailingSpaces(line);
    if (line.empty()) return false;
    if (characters(line) == 1) return true;
    // A number, with at most a closing mark or a unit of one character after it ("8", "8。", "8)").
    std::size_t digits = 0;
    while (digits < line.size() && (isDigit(line[digits]) || line[digits] == '.')) ++digits;
    return digits > 0 && characters(line.substr(digits)) <= 1;
}

}  // namespace

std::vector<std::string_view> lineBreakPieces(std::string_view text) {
    std::vector<std::string_view> pieces;
    if (text.empty()) return pieces;
    std::vector<std::size_t> ends;
    icu::BreakIterator* it = lineIterator();
    UErrorCode status = U_ZERO_ERROR;
    UText* utext = it ? utext_openUTF8(nullptr, text.data(), int64_t(text.size()), &status) : nullptr;
    if (utext && U_SUCCESS(status)) {
        it->setText(utext, status);
        if (U_SUCCESS(status)) {
            for (int32_t at = it->next(); at != icu::BreakIterator::DONE; at = it->next()) {
                if (at > 0 && std::size_t(at) <= text.size()) ends.push_back(std::size_t(at));
            }
        }
    }
    if (utext) {
        // The iterator keeps a pointer to the text: give it one that lives before the text goes.
        static const icu::UnicodeString nothing;
        it->setText(nothing);
        utext_close(utext);
    }
    if (ends.empty() || ends.back() != text.size()) ends.push_back(text.size());
    std::size_t start = 0;
    for (std::size_t end : ends) {
        if (end <= start) continue;
        // ICU's breaks fall on code points of the text as ICU read it; a broken byte sequence may put
        // one inside a character's bytes, which is kept whole.
        while (end < text.size() && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) ++end;
        if (end <= start) continue;
        const std::string_view piece = text.substr(start, end - start);
        if (!pieces.empty() &&
            (isNumberBeforeItsUnit(pieces.back(), piece) || isInsideAFraction(pieces.back(), piece))) {
            const std::size_t from = std::size_t(pieces.back().data() - text.data());
            pieces.back() = text.substr(from, end - from);
        } else {
            pieces.push_back(piece);
        }
        start = end;
    }
    return pieces;
}

std::vector<std::string> wrapLines(std::string_view text, float width, const TextMeasure& measure) {
    const std::vector<std::string_view> pieces = lineBreakPieces(text);
    // Each line as the pieces it holds: [first, end).
    std::vector<std::pair<std::size_t, std::size_t>> lines;
    std::size_t first = 0;
    auto lineText = [&](std::size_t from, std::size_t to) {
        if (from >= to) return std::string_view();
        const char* begin = pieces[from].data();
        const char* end = pieces[to - 1].data() + pieces[to - 1].size();
        return withoutTrailingSpaces(std::string_view(begin, std::size_t(end - begin)));
    };
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        if (i > first && measure(lineText(first, i + 1)) > width) {
            lines.emplace_back(first, i);
            first = i;
        }
    }
    if (first < pieces.size()) lines.emplace_back(first, pieces.size());
    // A lone last line takes the last piece of the line before along, while that line keeps some.
    if (lines.size() >= 2) {
        auto& last = lines.back();
        auto& before = lines[lines.size() - 2];
        if (isLone(lineText(last.first, last.second)) && before.second - before.first >= 2) {
            --before.second;
            --last.first;
        }
    }
    std::vector<std::string> out;
    for (const auto& [from, to] : lines) {
        const std::string_view line = lineText(from, to);
        if (!line.empty()) out.emplace_back(line);
    }
    return out;
}

}  // namespace fx
