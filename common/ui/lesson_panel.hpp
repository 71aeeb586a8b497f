#pragma once
// The lesson's own window: its steps (arrows move between them), shader errors, parameters with
// reset and presets, the lesson's panel, and a footer with the renderer, GL errors and the keys.
#include "ui/overlay_model.hpp"

namespace fx {

// The parameters that act in `step` (0-based), each with its widget and where its value came from;
// then, folded under "other steps", those that act only in other steps.
void drawParams(ParamSet& params, int step);
void drawLessonWindowContents(const OverlayModel& model);

}  // namespace fx
