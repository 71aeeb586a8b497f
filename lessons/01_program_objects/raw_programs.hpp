#pragma once
// Step 1 as the chapter found it: every program built by the same copy-pasted lines, and none of
// them checks whether compiling or linking worked. (The names are still owned, so nothing leaks.)
#include <filesystem>

#include "gl/object.hpp"

namespace lesson01 {

fx::gl::ProgramName buildProgramWithoutChecks(const std::filesystem::path& vertexFile,
                                              const std::filesystem::path& fragmentFile);

}  // namespace lesson01
