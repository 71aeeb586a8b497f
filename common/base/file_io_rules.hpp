#pragma once
// What file_io_posix.cpp and file_io_win.cpp share of the write rule (base/file_io.hpp).
#include <filesystem>
#include <optional>
#include <string>

namespace fx::detail {

// Why `name` is not a name inside the folder (empty, absolute, climbing out with ".."), or nothing.
std::optional<std::string> outsideTheFolder(const std::filesystem::path& name);

}  // namespace fx::detail
