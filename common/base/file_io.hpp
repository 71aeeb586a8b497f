#pragma once
// Reading whole files and writing them atomically: a file is either written completely or left as
// it was (write to a temporary file in the same folder, then rename over the target).
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "base/result.hpp"

namespace fx {

Result<std::string> readTextFile(const std::filesystem::path& path);

// Creates missing parent folders. On failure nothing is left at `path` or beside it.
Status writeFileAtomically(const std::filesystem::path& path, std::span<const std::byte> bytes);
Status writeFileAtomically(const std::filesystem::path& path, std::string_view text);

}  // namespace fx
