#pragma once
// Grades a scene exercise (kind "scene"): the student's file is a scene whose emitters must keep a
// particle budget and stay finite. GL-free: the scene is loaded as a lesson loads it (a scene past the
// limits is refused with the loader's message: file, field, reason) and its emitters are simulated on
// the CPU with the lesson's fixed rules for the exercise's seconds at 60 Hz, counting the particles
// alive at once and checking every live particle's numbers.
#include <filesystem>

#include "app/exercise_catalog.hpp"
#include "app/exercise_check.hpp"

namespace fx {

ExerciseVerdict checkSceneExercise(const Exercise& exercise, const std::filesystem::path& studentFile);

}  // namespace fx
