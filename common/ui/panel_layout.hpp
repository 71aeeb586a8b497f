#pragma once
// The presentation layout: where the overlay's windows go and where the lesson's picture goes, so that
// no panel ever covers the picture. The lesson and frame windows share a column on the left; the
// picture fills the rest of the window; an open inspector takes the lower part of that rest and the
// picture shrinks to the part above it. A collapsed inspector is a title bar at the column's foot.
// The lesson renders at the picture's size (FrameLoop), so it is never cropped or covered either.
//
// Every rectangle lies inside the window at every size, 1x1 included, and the picture overlaps none
// of the panels (tests/unit/app/test_panel_layout.cpp checks both over a sweep of sizes).
namespace fx {

// A rectangle in window pixels, top-left origin (ImGui's).
struct LayoutRect {
    float x = 0, y = 0, width = 0, height = 0;
    float right() const { return x + width; }
    float bottom() const { return y + height; }
    bool overlaps(const LayoutRect& o) const {
        return x < o.right() && o.x < right() && y < o.bottom() && o.y < bottom();
    }
    bool inside(float windowWidth, float windowHeight) const {
        return x >= 0 && y >= 0 && right() <= windowWidth && bottom() <= windowHeight;
    }
};

// What the user may change by dragging a panel's edge (kept in the settings file), as shares of the
// window so that they mean the same at every size. Reset layout puts these defaults back.
struct LayoutShares {
    float column = 0.30f;   // the left column's width, of the window's width
    float lesson = 0.62f;   // the lesson window's height, of the column's
    float picture = 0.42f;  // with the inspector open: the picture's height, of the window's
    bool operator==(const LayoutShares&) const = default;
};

// The shares brought into the range the layout uses (a settings file may hold anything).
LayoutShares clampShares(LayoutShares shares);

struct PanelLayout {
    LayoutRect lesson, frame, inspector, picture;
};

// titleHeight: one ImGui title bar at the current text scale (a collapsed window's height);
// minColumn: the narrowest the column may be, from the text scale (the column never takes more than
// 60% of the window, so the picture keeps at least 40% of the width).
PanelLayout computePanelLayout(int width, int height, const LayoutShares& shares, bool inspectorOpen,
                               float titleHeight, float minColumn);

// The largest rectangle of `aspect` (width / height) inside `place`, centred, in whole pixels: the
// picture keeps the aspect its lesson's text assumes at any window size, with a dark ground in the
// bars beside or above it. An aspect of 0 (or not finite) keeps the place as it is.
LayoutRect keepAspect(const LayoutRect& place, double aspect);

}  // namespace fx
