#pragma once
// The lesson's own window: its steps (arrows move between them), shader errors, parameters with
// reset and presets, the lesson's panel, and a footer with the renderer, GL errors and the keys.
#include "ui/overlay_model.hpp"

namespace fx {

void drawParams(ParamSet& params);
void drawLessonWindowContents(const OverlayModel& model);

}  // namespace fx
