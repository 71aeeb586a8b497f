#pragma once
// Where a line of text may break, by Unicode's line breaking rules (UAX #14, ICU's line
// BreakIterator with its Japanese rules): between words, between Japanese characters but never before
// a small kana, a prolonged sound mark or a closing mark (、。」）), never inside a number ("0.0000",
// "1280x720"). Two rules on top of ICU's: a number stays with the unit after it ("16 ms", "900 個"),
// and a wrapped text never leaves one character or a lone number alone on its last line.
// GL-free: the overlay measures with its font, the tests with a fixed width per character.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace fx {

// The text cut at every place a line may break: each piece holds the spaces after it, so the pieces
// joined give the text back.
std::vector<std::string_view> lineBreakPieces(std::string_view text);

// `measure` gives a piece of text's width in the same unit as `width`.
using TextMeasure = std::function<float(std::string_view)>;

// The text in lines at most `width` wide where it can be (a piece wider than the line alone gets a
// line of its own), spaces at a line's end dropped. A last line of one character or one number takes
// the piece before it along, so a title never ends on a lone "る" or "8".
std::vector<std::string> wrapLines(std::string_view text, float width, const TextMeasure& measure);

}  // namespace fx
