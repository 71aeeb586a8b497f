#pragma once
#include <memory>

#include "app/lesson.hpp"

namespace fx {

// Parses the command line, opens a window (or goes headless), runs the lesson, writes captures and
// the report. Returns the process exit code: 0 ok, 1 a run that failed, 2 a bad command line. The
// runner owns the lesson: it is destroyed while the GL context is still current, however the run
// ends, so a lesson releases its GL objects by destructors alone.
int runLesson(std::unique_ptr<Lesson> lesson, int argc, char** argv);

template <class L>
int runLesson(int argc, char** argv) {
    return runLesson(std::make_unique<L>(), argc, argv);
}

}  // namespace fx
