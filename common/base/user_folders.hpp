#pragma once
// The user's own folders, as each system names them: where settings live (Linux: $XDG_CONFIG_HOME,
// else ~/.config; Windows: %APPDATA%, the roaming application data) and the home folder (Linux: $HOME;
// Windows: %USERPROFILE%). Nothing when the system does not say (a bare environment).
#include <filesystem>
#include <optional>

namespace fx {

std::optional<std::filesystem::path> userConfigFolder();
std::optional<std::filesystem::path> userHomeFolder();

}  // namespace fx
