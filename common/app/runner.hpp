#pragma once
#include <memory>

#include "app/lesson.hpp"

namespace fx {

// Parses the command line, opens a window (or goes headless), runs the lesson, writes captures and
// the report. Returns the process exit code: 0 ok, 1 a run that failed, 2 a bad command line.
int runLesson(Lesson& lesson, int argc, char** argv);

template <class L>
int runLesson(int argc, char** argv) {
    auto lesson = std::make_unique<L>();
    return runLesson(*lesson, argc, argv);
}

}  // namespace fx
