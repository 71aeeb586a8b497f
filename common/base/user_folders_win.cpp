// The folders Windows keeps for the user, asked of the shell (the environment's APPDATA and
// USERPROFILE say the same, but a program started with a bare environment still gets them).
#include "base/user_folders.hpp"

#include <windows.h>
// windows.h first: the shell's headers need its types.
#include <knownfolders.h>
#include <shlobj.h>

namespace fx {
namespace {

std::optional<std::filesystem::path> knownFolder(const KNOWNFOLDERID& id) {
    wchar_t* path = nullptr;
    std::optional<std::filesystem::path> found;
    if (SHGetKnownFolderPath(id, 0, nullptr, &path) == S_OK && path && *path)
        found = std::filesystem::path(path);
    CoTaskMemFree(path);
    return found;
}

}  // namespace

std::optional<std::filesystem::path> userConfigFolder() {
    return knownFolder(FOLDERID_RoamingAppData);
}

std::optional<std::filesystem::path> userHomeFolder() {
    return knownFolder(FOLDERID_Profile);
}

}  // namespace fx
