#pragma once
#include <memory>

#include "app/lesson.hpp"

namespace fx {

// Parses the command line, opens a window (or goes headless), runs the lesson, writes captures and
// the report. Returns the process exit code: 0 ok, 1 a run that failed, 2 a bad command line. The
// runner owns the lesson: it is destroyed while the GL context is still current, however the run
// ends, so a lesson releases its GL objects by destructors alone.
int runLesson(std::unique_ptr<Lesson> lesson, LessonInfo info, int argc, char** argv);

template <class L>
int runLesson(LessonInfo info, int argc, char** argv) {
    return runLesson(std::make_unique<L>(), std::move(info), argc, argv);
}

}  // namespace fx

// The last line of a lesson's .cpp, and its main():
//
//   FX_LESSON(lesson04::ColourMatrixLesson, "Colour matrix", "scenes/04_colour_matrix.json")
//
// The title is the lesson's; the scene is a file under res/ ("": an empty scene). The number and the
// slug are the folder's: fxlab_add_lesson (cmake/FxLesson.cmake) checks the folder's name
// (lessons/04_colour_matrix) and passes them as FXLAB_LESSON_NUMBER and FXLAB_LESSON_SLUG, so a lesson
// built any other way does not compile.
#define FX_LESSON(LessonClass, title, defaultScene)                                                      \
    int main(int argc, char** argv) {                                                                    \
        return fx::runLesson<LessonClass>({FXLAB_LESSON_NUMBER, FXLAB_LESSON_SLUG, title, defaultScene}, \
                                          argc, argv);                                                   \
    }
