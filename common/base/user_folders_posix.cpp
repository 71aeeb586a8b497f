#include "base/user_folders.hpp"

#include <cstdlib>

namespace fx {
namespace {

std::optional<std::filesystem::path> fromEnvironment(const char* name) {
    const char* value = std::getenv(name);
    if (!value || !*value) return std::nullopt;
    return std::filesystem::path(value);
}

}  // namespace

std::optional<std::filesystem::path> userConfigFolder() {
    if (auto dir = fromEnvironment("XDG_CONFIG_HOME")) return dir;
    if (auto home = fromEnvironment("HOME")) return *home / ".config";
    return std::nullopt;
}

std::optional<std::filesystem::path> userHomeFolder() {
    return fromEnvironment("HOME");
}

}  // namespace fx
