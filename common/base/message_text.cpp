#include "base/message_text.hpp"

#include <charconv>
#include <cstdio>

namespace fx {
namespace {

template <class T>
std::string shortest(T value) {
    char buffer[64];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    if (ec != std::errc()) return "?";
    return std::string(buffer, end);
}

// One byte as the message shows it: printable bytes and UTF-8 as they are, the rest escaped.
void appendEscaped(std::string& out, char c) {
    const auto byte = static_cast<unsigned char>(c);
    switch (c) {
        case '\n':
            out += "\\n";
            return;
        case '\r':
            out += "\\r";
            return;
        case '\t':
            out += "\\t";
            return;
        default:
            break;
    }
    if (byte < 0x20 || byte == 0x7F) {
        char code[8];
        std::snprintf(code, sizeof code, "\\u%04x", unsigned(byte));
        out += code;
        return;
    }
    out += c;
}

}  // namespace

// Plain digits while they stay short (100000, 0.00025), else the exponent form (1e+20, 1e-300): the
// shortest form alone would print 100000 as 1e+05.
template <class T>
std::string readable(T value) {
    char buffer[64];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed);
    if (ec == std::errc() && end - buffer <= 24) return std::string(buffer, end);
    return shortest(value);
}

std::string formatNumber(double value) {
    return readable(value);
}

std::string formatNumber(float value) {
    return readable(value);
}

std::string formatNumber(long long value) {
    return shortest(value);
}

std::string excerpt(std::string_view text, std::size_t maxBytes) {
    std::size_t cut = text.size();
    if (text.size() > maxBytes) {
        cut = maxBytes;
        // Back up to the first byte of a UTF-8 character, so the excerpt does not end in half of one.
        while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    }
    std::string out;
    out.reserve(cut + 16);
    for (char c : text.substr(0, cut)) appendEscaped(out, c);
    if (cut < text.size()) out += "... (" + std::to_string(text.size()) + " bytes)";
    return out;
}

}  // namespace fx
