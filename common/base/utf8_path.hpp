#pragma once
// fxlab keeps text in UTF-8, paths included (a path's .string() is UTF-8 on every system). A path
// made from such text must say so: on Windows `std::filesystem::path(std::string)` reads the bytes in
// the C runtime's narrow encoding, not UTF-8, so "山田" would become other characters. pathFromUtf8
// is the one way in, wherever text from the command line, the environment or a file becomes a path;
// on Linux it is the plain conversion.
#include <filesystem>
#include <string>
#include <string_view>

namespace fx {

inline std::filesystem::path pathFromUtf8(std::string_view utf8) {
    return std::filesystem::path(std::u8string(utf8.begin(), utf8.end()));
}

}  // namespace fx
