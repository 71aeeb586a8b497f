#pragma once
// The keys and the mouse of a lesson window. Create it before the overlay: Dear ImGui's GLFW
// backend chains the key callback that was installed before it, so both see every key.
#include <string>
#include <vector>

#include "app/lesson.hpp"
#include "platform/context.hpp"

struct GLFWwindow;

namespace fx {

struct KeyPresses {
    bool next = false, previous = false, toggleOverlay = false, reload = false, screenshot = false;
    bool cancel = false;  // Esc while something long is under way (setEscapeCancels)
};

// The keys of a lesson window and what each does, for --help. The same table decides what a press
// does, so the help and the window cannot disagree.
struct WindowKeyHelp {
    std::string key, action;
};
std::vector<WindowKeyHelp> windowKeysHelp();

class WindowInput {
public:
    // window == nullptr (headless): no keys, no pointer.
    explicit WindowInput(GLFWwindow* window);
    ~WindowInput();
    WindowInput(const WindowInput&) = delete;
    WindowInput& operator=(const WindowInput&) = delete;

    // The presses since the last call (Esc closes the window directly, unless it cancels).
    KeyPresses takeKeyPresses();
    // While on, Esc cancels what is under way (the cost panel's sweep) instead of quitting.
    void setEscapeCancels(bool on);
    // The mouse in framebuffer pixels, bottom-left origin.
    Pointer pointer(Size2D framebuffer, bool overUi) const;

private:
    GLFWwindow* window_;
};

}  // namespace fx
