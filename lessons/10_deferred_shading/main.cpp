#include "app/runner.hpp"
#include "deferred_shading_lesson.hpp"

int main(int argc, char** argv) {
    return fx::runLesson<lesson10::DeferredShadingLesson>(argc, argv);
}
