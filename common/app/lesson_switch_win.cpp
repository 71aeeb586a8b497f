// The Windows side of lesson_switch.hpp. Windows has no exec: the neighbour is started with the same
// standard handles and this process ends at once, which is what the teacher sees of an exec (one
// window closes, the next opens). Paths and arguments go to CreateProcessW in UTF-16, quoted as the
// C runtime reads them back.
#include "app/lesson_switch.hpp"

#include <windows.h>

#include <cstdio>
#include <cwctype>

#include "base/log.hpp"
#include "base/windows_text.hpp"

namespace fx {

namespace fs = std::filesystem;

namespace {

std::wstring commandLine(const fs::path& executable, const std::vector<std::string>& args) {
    std::wstring line = windows::quoteArgument(executable.native());
    for (const std::string& a : args) line += L" " + windows::quoteArgument(windows::widen(a));
    return line;
}

bool hasExeSuffix(const fs::path& p) {
    std::wstring ext = p.extension().native();
    for (wchar_t& c : ext) c = wchar_t(std::towlower(c));
    return ext == L".exe";
}

struct Started {
    HANDLE process = nullptr;
    std::string error;
};

Started start(const fs::path& executable, const std::vector<std::string>& args, HANDLE output) {
    std::wstring line = commandLine(executable, args);
    STARTUPINFOW startup{};
    startup.cb = sizeof startup;
    if (output) {
        startup.dwFlags = STARTF_USESTDHANDLES;
        startup.hStdInput = GetStdHandle(STD_INPUT_HANDLE);
        startup.hStdOutput = output;
        startup.hStdError = output;
    }
    PROCESS_INFORMATION child{};
    std::fflush(nullptr);
    if (!CreateProcessW(executable.c_str(), line.data(), nullptr, nullptr, TRUE, 0, nullptr, nullptr,
                        &startup, &child))
        return {nullptr, cat("could not start ", executable.string(), ": ", windows::lastErrorText())};
    CloseHandle(child.hThread);
    return {child.hProcess, {}};
}

}  // namespace

bool isRunnableFile(const fs::directory_entry& entry) {
    std::error_code ec;
    return entry.is_regular_file(ec) && hasExeSuffix(entry.path());
}

std::string programName(const fs::path& executable) {
    return (hasExeSuffix(executable) ? executable.stem() : executable.filename()).string();
}

Error execLesson(const fs::path& executable, const std::vector<std::string>& args) {
    Started child = start(executable, args, nullptr);
    if (!child.process) return Error{child.error};
    CloseHandle(child.process);
    std::fflush(nullptr);
    ExitProcess(0);  // as exec: nothing of this run goes on
}

Result<int> runAndWait(const fs::path& executable, const std::vector<std::string>& args,
                       const fs::path& output) {
    HANDLE log = nullptr;
    if (!output.empty()) {
        SECURITY_ATTRIBUTES inherit{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
        log = CreateFileW(output.c_str(), GENERIC_WRITE, FILE_SHARE_READ, &inherit, CREATE_ALWAYS,
                          FILE_ATTRIBUTE_NORMAL, nullptr);
        if (log == INVALID_HANDLE_VALUE)
            return Error{cat(output.string(), ": cannot write (", windows::lastErrorText(), ")")};
    }
    Started child = start(executable, args, log);
    if (log) CloseHandle(log);
    if (!child.process) return Error{child.error};
    WaitForSingleObject(child.process, INFINITE);
    DWORD code = 0;
    const BOOL known = GetExitCodeProcess(child.process, &code);
    CloseHandle(child.process);
    if (!known) return Error{cat("waiting for ", executable.string(), ": ", windows::lastErrorText())};
    if (code >= 0xC0000000u) {
        char text[16];
        std::snprintf(text, sizeof text, "0x%08lX", static_cast<unsigned long>(code));
        return Error{cat(executable.string(), " ended by exception ", text)};
    }
    return int(code);
}

fs::path runningExecutable() {
    std::wstring buffer(MAX_PATH, L'\0');
    for (;;) {
        const DWORD n = GetModuleFileNameW(nullptr, buffer.data(), DWORD(buffer.size()));
        if (n == 0) return {};
        if (n < buffer.size()) return fs::path(buffer.substr(0, n));
        buffer.resize(buffer.size() * 2);
    }
}

}  // namespace fx
