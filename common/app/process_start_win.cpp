#include "app/process_start.hpp"

#include <windows.h>
// windows.h first: shellapi.h needs its types.
#include <shellapi.h>

#include <io.h>
#include <cstdio>

#include "base/windows_text.hpp"

namespace fx {
namespace {

// A GUI program has no standard handles of its own; one started from a console (cmd, PowerShell,
// fxlab.cmd) borrows that console's, unless its output was redirected (then the handles exist).
void attachParentConsole() {
    if (GetStdHandle(STD_ERROR_HANDLE) != nullptr) return;
    if (!AttachConsole(ATTACH_PARENT_PROCESS)) return;  // double-clicked: no console, none wanted
    FILE* ignored = nullptr;
    freopen_s(&ignored, "CONOUT$", "w", stdout);
    freopen_s(&ignored, "CONOUT$", "w", stderr);
}

}  // namespace

std::vector<std::string> programArguments(int argc, char** argv) {
    attachParentConsole();
    SetConsoleOutputCP(CP_UTF8);  // fxlab writes UTF-8 (the Japanese messages)
    int count = 0;
    wchar_t** wide = CommandLineToArgvW(GetCommandLineW(), &count);
    if (!wide) return std::vector<std::string>(argv + 1, argv + argc);
    std::vector<std::string> args;
    for (int i = 1; i < count; ++i) args.push_back(windows::narrow(wide[i]));
    LocalFree(wide);
    return args;
}

bool standardErrorIsTerminal() {
    return _isatty(_fileno(stderr)) != 0;
}

}  // namespace fx
