#pragma once
// Every pass of the frame in execution order (then those that did not run, greyed): its time in ms
// and as a share of the frame, how it was timed, why it did not run, the GL state it left for the
// next pass (from the executor's state check), and the textures it wrote. Below: how much texture
// memory the frame holds now and at most.
#include "render/frame_report.hpp"

namespace fx {

// The sum of the times of the passes that ran (what the shares are shares of).
double totalPassMs(const FrameReport& frame);

// copyMs > 0: one full-screen copy at this frame's size (the cost panel's last sweep measured it), so
// each pass's time also reads in copies, the bench's unit.
void drawPassTable(const FrameReport& frame, double copyMs = 0.0);

}  // namespace fx
