#pragma once
// The controls above the inspector's view: mip level, channel toggles, view transform, exposure,
// value range with auto-fit, depth linearisation, the NaN / Inf / negative highlight with its
// counts, and the histogram of the level's values with the range marked on it.
#include <imgui.h>

#include "ui/texture_analysis.hpp"
#include "ui/texture_source.hpp"
#include "ui/view_settings.hpp"

namespace fx {

// analysis may be null (not read yet).
void drawViewControls(ViewSettings& settings, const TextureSource& source, const TextureAnalysis* analysis);

// Fits the range to the finite values of the channels that are on; false when there are none.
bool autoFitRange(ViewSettings& settings, const TextureAnalysis& analysis);

// Bars per channel, a square-root count scale (so a few outliers still show), and the range as two
// lines; dragging in the histogram sets the range.
void drawHistogram(const TextureAnalysis& analysis, ViewSettings& settings, ImVec2 size);

}  // namespace fx
