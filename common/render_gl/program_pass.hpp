#pragma once
// A pass runs only when the programs it draws or dispatches with built. An effect builds its programs
// when it is made (each joins the run's gl::ProgramRegistry, so the runner shows the error and F5
// rebuilds); a pass that uses one that never built is declared not run, with the program's error as
// the reason the pass table shows, instead of drawing with nothing:
//
//   Pass& pass = graph.addPass("scene", body);
//   runsWith(pass, program_);
#include <vector>

#include "gl/program.hpp"
#include "render/pass.hpp"

namespace fx {

// Switches `pass` off ("the <label> program did not build: <error>") when `program` has no usable
// build; a program that built once and failed a reload keeps drawing with its last good build.
Pass& runsWith(Pass& pass, const gl::ReloadableProgram& program);

// Passes that only make sense together (a chain whose every level reads the one before): when one of
// them is switched off (a program that did not build), all of them are, with its reason.
void runTogether(const std::vector<Pass*>& passes);

}  // namespace fx
