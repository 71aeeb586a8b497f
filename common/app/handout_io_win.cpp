// findProgram on Windows: PATH's folders split at ';' (a folder may be quoted), each name tried with
// the suffixes of PATHEXT (".COM;.EXE;.BAT;..."), the first regular file found.
#include "app/handout_io.hpp"

#include <windows.h>

#include <vector>

#include "base/windows_text.hpp"

namespace fx::handout {

namespace fs = std::filesystem;

namespace {

std::wstring environment(const wchar_t* name) {
    const DWORD n = GetEnvironmentVariableW(name, nullptr, 0);
    if (n == 0) return {};
    std::wstring value(n, L'\0');
    value.resize(GetEnvironmentVariableW(name, value.data(), n));
    return value;
}

std::vector<std::wstring> split(const std::wstring& list) {
    std::vector<std::wstring> parts;
    std::size_t start = 0;
    while (start <= list.size()) {
        std::size_t end = list.find(L';', start);
        if (end == std::wstring::npos) end = list.size();
        std::wstring part = list.substr(start, end - start);
        if (part.size() >= 2 && part.front() == L'"' && part.back() == L'"')
            part = part.substr(1, part.size() - 2);
        if (!part.empty()) parts.push_back(part);
        start = end + 1;
    }
    return parts;
}

}  // namespace

fs::path findProgram(const std::string& name) {
    std::wstring suffixes = environment(L"PATHEXT");
    if (suffixes.empty()) suffixes = L".COM;.EXE;.BAT;.CMD";
    std::vector<std::wstring> tried{L""};
    for (const std::wstring& s : split(suffixes)) tried.push_back(s);
    const std::wstring wide = windows::widen(name);
    for (const std::wstring& dir : split(environment(L"PATH"))) {
        for (const std::wstring& suffix : tried) {
            const fs::path candidate = fs::path(dir) / (wide + suffix);
            std::error_code ec;
            if (fs::is_regular_file(candidate, ec)) return candidate;
        }
    }
    return {};
}

}  // namespace fx::handout
