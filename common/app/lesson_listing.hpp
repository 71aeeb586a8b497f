#pragma once
// What --list-steps and --list-params print, the executable's name for messages and out/, and the
// lesson's folder in the source tree (where its lesson.md is).
#include <filesystem>
#include <string>
#include <vector>

#include "app/lesson.hpp"
#include "app/lesson_text_files.hpp"

namespace fx {

std::string executableName(const LessonInfo& info);    // "fxlab-01-program-objects"
std::string lessonFolderName(const LessonInfo& info);  // "01-program-objects"
// <root>/lessons/01_program_objects: the folder name is the slug with '_' for '-' (cmake/ makes the
// executable's name from the folder's the other way round).
std::filesystem::path lessonSourceFolder(const LessonInfo& info);
// Every step's title and text as the overlay shows them; returns false (the error is logged)
// when the lesson's text files do not match its steps.
bool printSteps(const LessonTextFiles& text);
void printParams(const ParamSet& params);

}  // namespace fx
