#pragma once
// How a message shows what it is about: numbers in their shortest exact form, and text a user gave
// (a name on the command line, a key in a file) cut to a readable length with its control characters
// escaped. Every refusal that quotes a value goes through these, so a value and its limit read
// differently whenever they differ, and a 5,000-character name or a NUL byte cannot flood or cut a line.
#include <cstddef>
#include <string>
#include <string_view>

namespace fx {

// The shortest text that reads back as exactly this number (std::to_chars), in plain digits while they
// are short: 179.99999999, 2147483648, 100000, 0.1; 1e+20 past that. A float is shown as the float it
// is (0.1f as 0.1, not 0.100000001).
std::string formatNumber(double value);
std::string formatNumber(float value);
std::string formatNumber(long long value);
inline std::string formatNumber(int value) {
    return formatNumber(static_cast<long long>(value));
}

// The most bytes of a user's text a message quotes.
inline constexpr std::size_t kExcerptBytes = 48;

// `text` as a message quotes it: control characters escaped (\n, \t, \u0000 ...; a NUL byte no longer
// ends the line early), whole when short, else its first `maxBytes` bytes (cut at a character
// boundary), "..." and how long it was: "aaaa... (5000 bytes)".
std::string excerpt(std::string_view text, std::size_t maxBytes = kExcerptBytes);

}  // namespace fx
