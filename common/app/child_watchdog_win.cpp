// The Windows child of child_watchdog.hpp: no fork, so this program is started again as
// `PROGRAM --fx-child NAME ARG...` (CreateProcessW, the arguments quoted as the C runtime reads them
// back), its standard output is the answer, and it is ended with TerminateProcess when its time is up.
#include "app/child_watchdog.hpp"

#include <windows.h>

#include <chrono>
#include <cstdio>
#include <thread>

#include "base/log.hpp"
#include "base/windows_text.hpp"

namespace fx {
namespace {

std::wstring ownExecutable() {
    std::wstring buffer(MAX_PATH, L'\0');
    for (;;) {
        const DWORD n = GetModuleFileNameW(nullptr, buffer.data(), DWORD(buffer.size()));
        if (n == 0) return {};
        if (n < buffer.size()) return buffer.substr(0, n);
        buffer.resize(buffer.size() * 2);
    }
}

struct Closer {
    HANDLE h;
    ~Closer() {
        if (h && h != INVALID_HANDLE_VALUE) CloseHandle(h);
    }
};

}  // namespace

ChildOutcome runInChildWithin(const std::string& name, const std::vector<std::string>& arguments,
                              double seconds) {
    ChildOutcome outcome;
    if (!detail::findChildWork(name)) {
        outcome.reason = cat("no work named \"", name, "\"");
        return outcome;
    }
    const std::wstring program = ownExecutable();
    std::wstring commandLine = windows::quoteArgument(program) + L" " + windows::widen(detail::kChildFlag) +
                               L" " + windows::quoteArgument(windows::widen(name));
    for (const std::string& a : arguments) commandLine += L" " + windows::quoteArgument(windows::widen(a));

    SECURITY_ATTRIBUTES inherit{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
    HANDLE readEnd = nullptr, writeEnd = nullptr;
    if (!CreatePipe(&readEnd, &writeEnd, &inherit, 0)) {
        outcome.reason = cat("no pipe: ", windows::lastErrorText());
        return outcome;
    }
    Closer readCloser{readEnd};
    SetHandleInformation(readEnd, HANDLE_FLAG_INHERIT, 0);  // only the write end goes to the child
    STARTUPINFOW startup{};
    startup.cb = sizeof startup;
    startup.dwFlags = STARTF_USESTDHANDLES;
    startup.hStdInput = GetStdHandle(STD_INPUT_HANDLE);
    startup.hStdOutput = writeEnd;
    startup.hStdError = GetStdHandle(STD_ERROR_HANDLE);
    PROCESS_INFORMATION child{};
    std::fflush(nullptr);
    const BOOL started = CreateProcessW(program.c_str(), commandLine.data(), nullptr, nullptr, TRUE,
                                        CREATE_NO_WINDOW, nullptr, nullptr, &startup, &child);
    const DWORD startError = GetLastError();
    CloseHandle(writeEnd);  // ours: the pipe ends when the child's copy closes
    if (!started) {
        outcome.reason =
            cat("could not start ", windows::narrow(program), ": ", windows::errorText(startError));
        return outcome;
    }
    Closer processCloser{child.hProcess};
    Closer threadCloser{child.hThread};

    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    bool timedOut = false;
    for (;;) {
        DWORD waiting = 0;
        if (!PeekNamedPipe(readEnd, nullptr, 0, nullptr, &waiting, nullptr)) break;  // the child closed it
        if (waiting > 0) {
            char buffer[4096];
            DWORD n = 0;
            if (!ReadFile(readEnd, buffer, std::min<DWORD>(waiting, sizeof buffer), &n, nullptr) || n == 0)
                break;
            outcome.answer.append(buffer, n);
            continue;
        }
        if (std::chrono::steady_clock::now() >= deadline) {
            timedOut = true;
            break;
        }
        // Nothing to read yet: wait a little for the child to end or to write.
        WaitForSingleObject(child.hProcess, 10);
    }
    if (timedOut) TerminateProcess(child.hProcess, 1);  // our own child, by its handle
    WaitForSingleObject(child.hProcess, INFINITE);
    DWORD code = 0;
    GetExitCodeProcess(child.hProcess, &code);
    if (timedOut) {
        outcome.kind = ChildOutcome::Kind::timedOut;
    } else if (code != 0) {
        // runChildWorkIfAsked returns 0; anything else is an abort (3), an exception (0xC0000005 ...)
        // or a work that could not write its answer.
        outcome.kind = ChildOutcome::Kind::crashed;
        char text[32];
        std::snprintf(text, sizeof text, code >= 0xC0000000u ? "exception 0x%08lX" : "exit code %lu",
                      static_cast<unsigned long>(code));
        outcome.reason = text;
    } else {
        outcome.kind = ChildOutcome::Kind::finished;
    }
    return outcome;
}

}  // namespace fx
