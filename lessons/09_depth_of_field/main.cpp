#include "app/runner.hpp"
#include "depth_of_field_lesson.hpp"

int main(int argc, char** argv) {
    return fx::runLesson<lesson09::DepthOfFieldLesson>(argc, argv);
}
