#pragma once
// The inspector's large view of one texture level: zoom with the mouse wheel (down to single
// texels, which get a grid), pan by dragging, double-click to fit, right-click to pin the probe.
// What it shows is drawn by TextureDisplay into a surface of exactly the view's size.
#include <optional>

#include <imgui.h>

#include "ui/pixel_probe.hpp"
#include "ui/texture_display.hpp"

namespace fx {

class ZoomableView {
public:
    struct Interaction {
        std::optional<PixelProbe::Target> hovered;  // the texel under the mouse
        bool pinRequested = false;                  // right click: pin (or release) the probe there
    };

    // Draws the view in a `size` region at the cursor. `mark` outlines the probed texel.
    Interaction draw(const TextureDisplay& display, const TextureSource& source, const ViewSettings& settings,
                     ImVec2 size, const std::optional<PixelProbe::Target>& mark);

    // Zoom is in screen pixels per texel of level 0, so changing the mip level keeps the picture
    // where it is and shows the smaller level's texels as larger squares.
    void fit() { fit_ = true; }
    void setZoom(double pixelsPerTexel, double centreU, double centreV);
    double zoom() const { return zoom_; }
    bool fitted() const { return fit_; }

private:
    ViewWindow windowFor(const TextureSource& source, int level, int width, int height) const;

    DisplaySurface surface_{"ui.inspector view"};
    double zoom_ = 1.0;
    double centreU_ = 0.5, centreV_ = 0.5;  // the level's point at the centre of the view, in [0, 1]
    bool fit_ = true;
};

}  // namespace fx
