#pragma once
// Turns a byte offset into the line and column an editor shows, for JSON syntax errors.
#include <cstddef>
#include <string_view>

namespace fx {

struct TextPosition {
    std::size_t line = 1;    // 1-based
    std::size_t column = 1;  // 1-based, in characters: a UTF-8 sequence counts once, a tab counts once
};

// Position of the byte at `offset` (0-based). An offset past the end gives the position just after the
// last character, which is where "unexpected end of input" belongs.
TextPosition textPositionOf(std::string_view text, std::size_t offset);

}  // namespace fx
