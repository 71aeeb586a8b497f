#include "app/runner.hpp"
#include "colour_matrix_lesson.hpp"

int main(int argc, char** argv) {
    return fx::runLesson<lesson04::ColourMatrixLesson>(argc, argv);
}
