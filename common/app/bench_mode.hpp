#pragma once
// `--bench`: sweep the lesson's quality knobs instead of running frames, print the table and write
// the bench outputs. Returns the exit code (0 ok, 1 failed, 2 an unknown --knob).
#include "app/frame_renderer.hpp"
#include "app/run_session.hpp"

namespace fx {

int runBenchMode(RunSession& session, FrameRenderer& renderer, Context& context);

}  // namespace fx
