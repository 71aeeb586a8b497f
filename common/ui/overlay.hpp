#pragma once
// The Dear ImGui overlay: the lesson's steps (left/right arrows move between them), its
// parameters, the frame's passes with their times and reasons, shader errors, and the lesson's own
// panel. In a window it follows GLFW input; headless (--overlay) it draws at the capture's size.
#include <functional>
#include <string>
#include <vector>

#include "base/params.hpp"
#include "render/frame_graph.hpp"
#include "render/frame_report.hpp"
#include "render/quality_sweep.hpp"

struct GLFWwindow;

namespace fx {

struct OverlayStep {
    std::string title, text;
};

struct OverlayModel {
    std::string title;
    std::vector<OverlayStep> steps;
    int* step = nullptr;  // 0-based, the overlay may change it
    ParamSet* params = nullptr;
    const FrameReport* frame = nullptr;
    // The frame's graph while its inspected textures are still held (the inspector reads them).
    const FrameGraph* graph = nullptr;
    std::string timing;        // method and why
    std::string renderer;
    double frameMs = 0;
    std::int64_t glErrors = 0;
    std::int64_t glExpectedErrors = 0;
    std::vector<std::string> shaderErrors;  // shown until fixed (the last good program keeps running)
    std::string status;                     // one line: "saved out/screenshot-3.png", "reloaded shaders"
    std::function<void()> lessonPanel;
    std::function<void()> onSavePreset, onLoadPreset;
    // The camera's planes, for showing depth textures linearised.
    float cameraNear = 0.1f, cameraFar = 100.0f;
    // Runs the quality-knob sweep in the app (as ./fxlab bench does) and returns its points; empty
    // when the lesson has no knobs.
    std::function<SweepResult()> measureKnobs;
};

class Overlay {
public:
    // window == nullptr: headless, no input.
    explicit Overlay(GLFWwindow* window);
    ~Overlay();
    Overlay(const Overlay&) = delete;
    Overlay& operator=(const Overlay&) = delete;

    bool ok() const { return ok_; }
    void draw(const OverlayModel& model, int width, int height, double deltaSeconds);
    bool wantsKeyboard() const;
    // Names of the textures the overlay wants to show next frame; the runner marks them inspected,
    // which keeps them (and the passes that make them) alive.
    std::vector<std::string> wantedTextures() const { return {}; }
    bool wantsMouse() const;

private:
    GLFWwindow* window_;
    bool ok_ = false;
};

}  // namespace fx
