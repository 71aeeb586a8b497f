#include "app/runner.hpp"
#include "skinned_shadows_lesson.hpp"

int main(int argc, char** argv) {
    return fx::runLesson<lesson02::SkinnedShadowsLesson>(argc, argv);
}
