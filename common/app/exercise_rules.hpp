#pragma once
// What makes a student's file one the check grades: a regular file (not a FIFO, a folder or a link to a
// device, each said as what it is), and the student's own, not a link into the exercises' answers
// (exercises/solutions/). A shader's #include is held to the same folders by gl/shader_source.
#include <filesystem>
#include <optional>
#include <string>

namespace fx {

// Why `file` (which exists) is not a file the check can read, or nothing; nothing too when it is
// missing (the check says how to start the exercise).
std::optional<std::string> whyNotAStudentsFile(const std::filesystem::path& file);
// Why `file` is not the student's own work: it resolves (through links) into exercises/solutions/.
std::optional<std::string> whyNotTheStudentsOwn(const std::filesystem::path& file);

}  // namespace fx
