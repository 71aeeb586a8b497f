#pragma once
// The Dear ImGui overlay, in three windows:
//   - the lesson: its steps (left/right arrows move between them), parameters, shader errors and the
//     lesson's own panel (lesson_panel);
//   - the frame: every pass with its time, share, reason and leaked state (pass_table), and the cost
//     of the quality knobs (cost_panel);
//   - the inspector: every texture of the frame, one of them large with its chain and a pixel probe
//     (inspector).
// In a window it follows GLFW input; headless (--overlay) it draws at the capture's size. See
// docs/overlay.md.
#include <memory>
#include <string>
#include <vector>

#include "ui/cost_panel.hpp"
#include "ui/imgui_backend.hpp"
#include "ui/inspector.hpp"
#include "ui/overlay_fonts.hpp"
#include "ui/overlay_model.hpp"

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
    // Names of the textures the overlay wants to show next frame; the runner marks them inspected,
    // which keeps them (and the passes that make them) alive.
    std::vector<std::string> wantedTextures() const;
    bool wantsMouse() const;

    // The panels, for tests, tools and documentation pictures (what a user does with the mouse).
    Inspector& inspector() { return *inspector_; }
    CostPanel& costPanel() { return cost_; }
    // Opens or collapses the frame window (passes and cost) and picks its tab.
    void showFramePanel(bool open, bool costTab = false);

private:
    void prepareFonts(const OverlayModel& model);

    GLFWwindow* window_;
    ImGuiBackends started_;
    std::unique_ptr<Inspector> inspector_;
    CostPanel cost_;
    OverlayFonts fonts_;
    int fontsForRevision_ = -1;  // the text revision the font atlas was made for
    std::string fontError_;      // shown in the lesson window while it stands
    bool fontTextureLabelled_ = false;
    std::optional<bool> requestFrameOpen_;
    bool requestCostTab_ = false;
};

}  // namespace fx
