#include "app/runner.hpp"
#include "program_objects_lesson.hpp"

int main(int argc, char** argv) {
    return fx::runLesson<lesson01::ProgramObjectsLesson>(argc, argv);
}
