#pragma once
// What a run leaves behind: the captures (final.png and every texture of the last frame) and the
// JSON report, with the lesson's facts for its last frame.
#include "app/frame_loop.hpp"

namespace fx {

// Returns 0, or 1 when something could not be written.
int writeRunResults(RunSession& session, const RunPlan& plan, Context& context,
                    const gl::ProgramRegistry& programs, RunRecord& record);

}  // namespace fx
