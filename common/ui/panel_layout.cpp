#include "ui/panel_layout.hpp"

#include <algorithm>
#include <cmath>

namespace fx {

LayoutShares clampShares(LayoutShares s) {
    auto clampShare = [](float v, float low, float high, float fallback) {
        return std::isfinite(v) ? std::clamp(v, low, high) : fallback;
    };
    const LayoutShares defaults;
    s.column = clampShare(s.column, 0.15f, 0.60f, defaults.column);
    s.lesson = clampShare(s.lesson, 0.20f, 0.90f, defaults.lesson);
    s.picture = clampShare(s.picture, 0.20f, 0.80f, defaults.picture);
    return s;
}

PanelLayout computePanelLayout(int width, int height, const LayoutShares& given, bool inspectorOpen,
                               float titleHeight, float minColumn) {
    const LayoutShares s = clampShares(given);
    const float w = float(std::max(width, 0)), h = float(std::max(height, 0));
    const float title = std::clamp(titleHeight, 0.0f, h);
    // Whole pixels, so that the picture is a whole number of pixels and starts on one.
    const float column = std::floor(std::clamp(std::max(s.column * w, minColumn), 0.0f, 0.6f * w));
    PanelLayout l;
    // The inspector's title bar stays at the column's foot while it is collapsed.
    const float columnBody = inspectorOpen ? h : std::max(h - title, 0.0f);
    const float lessonHeight =
        std::floor(std::clamp(s.lesson * columnBody, std::min(title, columnBody), columnBody));
    l.lesson = {0, 0, column, lessonHeight};
    l.frame = {0, lessonHeight, column, columnBody - lessonHeight};
    const float rest = w - column;
    if (inspectorOpen) {
        const float pictureHeight = std::floor(s.picture * h);
        l.picture = {column, 0, rest, pictureHeight};
        l.inspector = {column, pictureHeight, rest, h - pictureHeight};
    } else {
        l.picture = {column, 0, rest, h};
        l.inspector = {0, columnBody, column, h - columnBody};
    }
    return l;
}

LayoutRect keepAspect(const LayoutRect& place, double aspect) {
    if (!(aspect > 0) || !std::isfinite(aspect) || place.width < 1 || place.height < 1) return place;
    // Round to the nearest whole pixel, at least one: a 1x1 place still gets a 1x1 picture.
    float width = place.width, height = std::max(1.0f, std::round(place.width / float(aspect)));
    if (height > place.height) {
        height = place.height;
        width = std::clamp(std::round(place.height * float(aspect)), 1.0f, place.width);
    }
    return {place.x + std::floor((place.width - width) * 0.5f),
            place.y + std::floor((place.height - height) * 0.5f), width, height};
}

}  // namespace fx
