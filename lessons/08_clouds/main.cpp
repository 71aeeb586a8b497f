#include "app/runner.hpp"
#include "clouds_lesson.hpp"

int main(int argc, char** argv) {
    return fx::runLesson<lesson08::CloudsLesson>(argc, argv);
}
