#pragma once
// Step 1 as the chapter found it: every program built by the same copy-pasted lines, and none of
// them checks whether compiling or linking worked. (The names are still owned, so nothing leaks, and
// labelled, so a debugger names them.)
#include <filesystem>
#include <string>

#include "gl/object.hpp"

namespace lesson01 {

// `label` names the program in debuggers; its shaders get "<label>.vert" and "<label>.frag".
fx::gl::ProgramName buildProgramWithoutChecks(const std::filesystem::path& vertexFile,
                                              const std::filesystem::path& fragmentFile,
                                              const std::string& label);

}  // namespace lesson01
