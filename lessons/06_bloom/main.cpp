#include "app/runner.hpp"
#include "bloom_lesson.hpp"

int main(int argc, char** argv) {
    return fx::runLesson<lesson06::BloomLesson>(argc, argv);
}
