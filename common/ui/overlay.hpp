#pragma once
// The Dear ImGui overlay, in three windows, docked in the presentation layout (ui/panel_layout.hpp) so
// that none of them covers the lesson's picture:
//   - the lesson: its steps (left/right arrows move between them), parameters, shader errors and the
//     lesson's own panel (lesson_panel);
//   - the frame: every pass with its time, share, reason and leaked state (pass_table), and the cost
//     of the quality knobs (cost_panel);
//   - the inspector: every texture of the frame, one of them large with its chain and a pixel probe
//     (inspector).
// Dragging a window's inner edge moves the layout's borders; the text scale (+ and -) rasterises the
// font at that size. In a window it follows GLFW input; headless (--overlay) it draws at the capture's
// size. See docs/overlay.md.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ui/cost_panel.hpp"
#include "ui/imgui_backend.hpp"
#include "ui/inspector.hpp"
#include "ui/key_latch.hpp"
#include "ui/overlay_fonts.hpp"
#include "ui/overlay_model.hpp"
#include "ui/panel_layout.hpp"

struct GLFWwindow;

namespace fx {

class Overlay {
public:
    // window == nullptr: headless, no input.
    explicit Overlay(GLFWwindow* window);
    ~Overlay();
    Overlay(const Overlay&) = delete;
    Overlay& operator=(const Overlay&) = delete;

    bool ok() const { return started_.renderer; }
    // Draws into the framebuffer bound now, at width x height. GL state is left as it was found.
    void draw(const OverlayModel& model, int width, int height, double deltaSeconds);
    bool wantsKeyboard() const;
    // A text field is being edited (or a widget held): the keys it uses are its own (FrameLoop::takeKeys).
    bool wantsTextInput() const;
    // Names of the textures the overlay wants to show next frame; the runner marks them inspected,
    // which keeps them (and the passes that make them) alive.
    std::vector<std::string> wantedTextures() const;
    bool wantsMouse() const;

    // The panels, for tests, tools and documentation pictures (what a user does with the mouse).
    Inspector& inspector() { return *inspector_; }
    CostPanel& costPanel() { return cost_; }
    // Opens or collapses the frame window (passes and cost) and picks its tab.
    void showFramePanel(bool open, bool costTab = false);

    // Where the panels and the picture go at this size, with the inspector open or collapsed as it
    // was last drawn. The runner renders the lesson at layout(...).picture's size.
    PanelLayout layout(int width, int height) const;
    LayoutShares shares() const { return shares_; }
    void setShares(const LayoutShares& shares) { shares_ = clampShares(shares); }
    // The text scale: 1 is Dear ImGui's 13-pixel font. Applied at the next draw.
    float textScale() const { return textScale_; }
    void setTextScale(float scale) { textScale_ = scale; }
    // The default shares back, the inspector collapsed (the text scale stays).
    void resetLayout();

private:
    void prepareFonts(const OverlayModel& model);
    void applyTextScale();
    void drawFrameWindow(const OverlayModel& model, const PanelLayout& layout);
    // A docked window's size after the user dragged its edge: the shares follow it.
    void followResize(const LayoutRect& placed, ImVec2 now, int width, int height, bool lessonWindow);

    GLFWwindow* window_;
    ImGuiBackends started_;
    std::unique_ptr<KeyLatch> keys_;  // in a window: no key press is lost between two frames
    std::unique_ptr<Inspector> inspector_;
    CostPanel cost_;
    OverlayFonts fonts_;
    int fontsForRevision_ = -1;  // the text revision the font atlas was made for
    std::string fontError_;      // shown in the lesson window while it stands
    bool fontTextureLabelled_ = false;
    std::optional<bool> requestFrameOpen_;
    bool requestCostTab_ = false;
    LayoutShares shares_;
    float textScale_ = 1.0f;
    float appliedScale_ = 0.0f;  // the scale the fonts and the style were made for
    ImGuiStyle baseStyle_;       // the style at scale 1
};

}  // namespace fx
