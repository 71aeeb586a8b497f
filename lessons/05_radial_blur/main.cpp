#include "app/runner.hpp"
#include "radial_blur_lesson.hpp"

int main(int argc, char** argv) {
    return fx::runLesson<lesson05::RadialBlurLesson>(argc, argv);
}
