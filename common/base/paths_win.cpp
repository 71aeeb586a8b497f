#include "base/installed_root.hpp"

#include <windows.h>

#include <string>

namespace fx {

// The unpacked zip holds the .exe's beside shaders/ and res/; the build tree's .exe's do not, and use
// the source root they were built from.
std::optional<std::filesystem::path> installedRoot() {
    std::wstring buffer(MAX_PATH, L'\0');
    for (;;) {
        const DWORD n = GetModuleFileNameW(nullptr, buffer.data(), DWORD(buffer.size()));
        if (n == 0) return std::nullopt;
        if (n < buffer.size()) {
            buffer.resize(n);
            break;
        }
        buffer.resize(buffer.size() * 2);
    }
    const std::filesystem::path folder = std::filesystem::path(buffer).parent_path();
    std::error_code ec;
    if (std::filesystem::is_directory(folder / "shaders", ec) &&
        std::filesystem::is_directory(folder / "res", ec))
        return folder;
    return std::nullopt;
}

}  // namespace fx
