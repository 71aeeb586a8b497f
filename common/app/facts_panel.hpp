#pragma once
// The lesson's facts in the overlay: one "label: value" line each (a progress bar for work spread over
// frames), above the lesson's own panel.
#include "app/lesson_facts.hpp"
#include "base/size2d.hpp"

namespace fx {

// `picture`: the size the facts were computed at (a number in pixels holds for it), said first.
void drawFacts(const Facts& facts, Size2D picture);

}  // namespace fx
