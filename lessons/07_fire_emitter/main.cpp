#include "app/runner.hpp"
#include "fire_lesson.hpp"

int main(int argc, char** argv) {
    return fx::runLesson<lesson07::FireLesson>(argc, argv);
}
