#include "app/runner.hpp"
#include "fbo_pipeline_lesson.hpp"

int main(int argc, char** argv) {
    return fx::runLesson<lesson03::FboPipelineLesson>(argc, argv);
}
