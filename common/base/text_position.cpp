#include "base/text_position.hpp"

#include <algorithm>

namespace fx {

TextPosition textPositionOf(std::string_view text, std::size_t offset) {
    TextPosition position;
    std::size_t end = std::min(offset, text.size());
    for (std::size_t i = 0; i < end; ++i) {
        auto byte = static_cast<unsigned char>(text[i]);
        if (byte == '\n') {
            ++position.line;
            position.column = 1;
        } else if ((byte & 0xC0) != 0x80) {  // continuation bytes belong to the character before them
            ++position.column;
        }
    }
    return position;
}

}  // namespace fx
