#include "app/window_input.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace fx {
namespace {

struct WindowKey {
    int key;           // GLFW_KEY_*
    const char* name;  // as --help shows it
    const char* action;
    bool KeyPresses::*press;  // what a press sets; nullptr: Esc, which closes the window
};

constexpr WindowKey kWindowKeys[] = {
    {GLFW_KEY_LEFT, "left arrow", "previous step", &KeyPresses::previous},
    {GLFW_KEY_RIGHT, "right arrow", "next step", &KeyPresses::next},
    {GLFW_KEY_F1, "F1", "show or hide the overlay", &KeyPresses::toggleOverlay},
    {GLFW_KEY_F5, "F5", "reload shaders (they also reload when saved)", &KeyPresses::reload},
    {GLFW_KEY_F12, "F12", "save a screenshot to out/", &KeyPresses::screenshot},
    {GLFW_KEY_ESCAPE, "Esc", "quit", nullptr},
};

// GLFW callbacks are plain functions: the presses of the one lesson window go here.
KeyPresses* pending = nullptr;
KeyPresses presses;
bool escapeCancels = false;

void onKey(GLFWwindow* window, int key, int, int action, int) {
    if (action != GLFW_PRESS || !pending) return;
    for (const WindowKey& k : kWindowKeys) {
        if (k.key != key) continue;
        if (k.press)
            pending->*k.press = true;
        else if (escapeCancels)
            pending->cancel = true;
        else
            glfwSetWindowShouldClose(window, GLFW_TRUE);
    }
}

}  // namespace

std::vector<WindowKeyHelp> windowKeysHelp() {
    std::vector<WindowKeyHelp> keys;
    for (const WindowKey& k : kWindowKeys) keys.push_back({k.name, k.action});
    return keys;
}

WindowInput::WindowInput(GLFWwindow* window) : window_(window) {
    if (!window_) return;
    presses = {};
    pending = &presses;
    glfwSetKeyCallback(window_, onKey);
}

WindowInput::~WindowInput() {
    if (window_) pending = nullptr;
}

KeyPresses WindowInput::takeKeyPresses() {
    KeyPresses taken = presses;
    presses = {};
    return window_ ? taken : KeyPresses{};
}

void WindowInput::setEscapeCancels(bool on) {
    escapeCancels = on;
}

Pointer WindowInput::pointer(Size2D framebuffer, bool overUi) const {
    Pointer p;
    if (!window_ || framebuffer.empty()) return p;
    double x = 0, y = 0;
    glfwGetCursorPos(window_, &x, &y);
    int windowWidth = 0, windowHeight = 0;
    glfwGetWindowSize(window_, &windowWidth, &windowHeight);
    if (windowWidth <= 0 || windowHeight <= 0) return p;
    // Window coordinates (top-left origin, screen units) to framebuffer pixels (bottom-left origin).
    double sx = double(framebuffer.width) / windowWidth, sy = double(framebuffer.height) / windowHeight;
    p.x = float(x * sx);
    p.y = float(framebuffer.height - y * sy);
    p.present = x >= 0 && y >= 0 && x < windowWidth && y < windowHeight;
    p.leftDown = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    p.overUi = overUi;
    return p;
}

}  // namespace fx
