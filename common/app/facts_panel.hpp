#pragma once
// The lesson's facts in the overlay: one "label: value" line each, above the lesson's own panel.
#include "app/lesson_facts.hpp"

namespace fx {

void drawFacts(const Facts& facts);

}  // namespace fx
