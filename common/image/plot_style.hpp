#pragma once
// Sizes and wording shared by the plot's layout (plot_layout.cpp) and its painter (plot.cpp), so the
// space the layout reserves is the space the painter uses.
#include <string>

#include "image/canvas_text.hpp"
#include "image/plot.hpp"

namespace fx::plot_style {

inline constexpr double kTextScale = 2.0;  // the font is 7 pixels tall at scale 1: too small to read
inline constexpr double kTitleScale = 3.0;
inline constexpr double kMargin = 16.0;  // between the picture's edge and anything drawn
inline constexpr double kTickLength = 6.0;
inline constexpr double kTickLabelGap = 6.0;  // between a tick mark and its label
inline constexpr double kLabelGap = 12.0;     // between the tick labels and the axis label
inline constexpr double kNoteSpacing = 8.0;   // between lines of notes

inline double lineHeight() {
    return measureText("0", kTextScale).height;
}

// What a point is called on the picture: its label, with its role when it has one.
inline std::string displayLabel(const PlotPoint& point) {
    std::string label = point.label;
    if (point.isReference) label += label.empty() ? "reference" : " (reference)";
    if (point.isCurrent) label += label.empty() ? "current" : " (current)";
    return label;
}

}  // namespace fx::plot_style
