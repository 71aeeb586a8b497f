#pragma once
// Windows only (windows_text_win.cpp): fxlab keeps text and paths in UTF-8; Windows' wide (UTF-16)
// functions take them at the edge, and their errors come back as UTF-8 sentences.
#include <string>
#include <string_view>

namespace fx::windows {

std::wstring widen(std::string_view utf8);
std::string narrow(std::wstring_view wide);
// The system's sentence for an error code (GetLastError), without the trailing line break.
std::string errorText(unsigned long code);
// errorText(GetLastError()).
std::string lastErrorText();
// One argument of a command line as CommandLineToArgvW and the C runtime read it back.
std::wstring quoteArgument(std::wstring_view argument);

}  // namespace fx::windows
