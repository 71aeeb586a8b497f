#pragma once
// What --list-steps and --list-params print, and the executable's name for messages and out/.
#include <string>
#include <vector>

#include "app/lesson.hpp"

namespace fx {

std::string executableName(const LessonInfo& info);  // "fxlab-01-program-objects"
std::string lessonFolderName(const LessonInfo& info);  // "01-program-objects"
void printSteps(const std::vector<LessonStep>& steps);
void printParams(const ParamSet& params);

}  // namespace fx
