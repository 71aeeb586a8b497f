#include "ui/key_latch.hpp"

#include <deque>
#include <vector>

#include <imgui.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace fx {
namespace {

// GLFW callbacks are plain functions: the one overlay window's presses go here.
GLFWkeyfun backendCallback = nullptr;
GLFWmousebuttonfun backendMouseCallback = nullptr;
std::vector<int> pressedSinceFrame;
std::vector<int> heldForImGui;  // forced down for the frame that just began

// A mouse button went down or up, and where the cursor was then (window coordinates).
struct MouseEvent {
    int button;
    bool down;
    double x, y;
};
std::deque<MouseEvent> mouseEvents;
constexpr std::size_t kMostMouseEvents = 256;
constexpr int kButtons = int(sizeof(ImGuiIO::MouseDown) / sizeof(ImGuiIO::MouseDown[0]));

constexpr int kKeys = int(sizeof(ImGuiIO::KeysDown) / sizeof(ImGuiIO::KeysDown[0]));

bool isModifier(int key) {
    return key == GLFW_KEY_LEFT_CONTROL || key == GLFW_KEY_RIGHT_CONTROL || key == GLFW_KEY_LEFT_SHIFT ||
           key == GLFW_KEY_RIGHT_SHIFT || key == GLFW_KEY_LEFT_ALT || key == GLFW_KEY_RIGHT_ALT ||
           key == GLFW_KEY_LEFT_SUPER || key == GLFW_KEY_RIGHT_SUPER;
}

void onKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
    // A press, and a modifier let go: a Ctrl held across a click, and released before the frame that
    // sees the click, still makes it a Ctrl+click.
    const bool inRange = key >= 0 && key < kKeys;
    if (inRange && (action == GLFW_PRESS || (action == GLFW_RELEASE && isModifier(key))))
        pressedSinceFrame.push_back(key);
    if (backendCallback) backendCallback(window, key, scancode, action, mods);
}

void onMouseButton(GLFWwindow* window, int button, int action, int mods) {
    if (button >= 0 && button < kButtons && (action == GLFW_PRESS || action == GLFW_RELEASE) &&
        mouseEvents.size() < kMostMouseEvents) {
        MouseEvent e{button, action == GLFW_PRESS, 0, 0};
        glfwGetCursorPos(window, &e.x, &e.y);
        mouseEvents.push_back(e);
    }
    if (backendMouseCallback) backendMouseCallback(window, button, action, mods);
}

// The oldest queued mouse event, as this frame's state: the cursor where it was and the button as it
// was then. The backend has just set both from the present state; with nothing queued, that stands.
void replayMouse() {
    if (mouseEvents.empty()) return;
    const MouseEvent e = mouseEvents.front();
    mouseEvents.pop_front();
    ImGuiIO& io = ImGui::GetIO();
    // In window coordinates, as the backend's own (glfwGetCursorPos).
    io.MousePos = ImVec2(float(e.x), float(e.y));
    io.MouseDown[e.button] = e.down;
}

}  // namespace

KeyLatch::KeyLatch(GLFWwindow* window) : window_(window) {
    pressedSinceFrame.clear();
    heldForImGui.clear();
    mouseEvents.clear();
    backendCallback = glfwSetKeyCallback(window_, onKey);
    backendMouseCallback = glfwSetMouseButtonCallback(window_, onMouseButton);
}

KeyLatch::~KeyLatch() {
    glfwSetKeyCallback(window_, backendCallback);
    glfwSetMouseButtonCallback(window_, backendMouseCallback);
    backendCallback = nullptr;
    backendMouseCallback = nullptr;
}

void KeyLatch::beforeNewFrame() {
    ImGuiIO& io = ImGui::GetIO();
    for (int key : heldForImGui) {
        if (glfwGetKey(window_, key) != GLFW_PRESS) io.KeysDown[key] = false;
    }
    heldForImGui.clear();
    for (int key : pressedSinceFrame) {
        if (io.KeysDown[key]) continue;  // still held: the backend's state already says so
        io.KeysDown[key] = true;
        heldForImGui.push_back(key);
    }
    pressedSinceFrame.clear();
    replayMouse();
    // The backend sets the modifiers from the keys in its callback; a Ctrl held for ImGui counts too
    // (a quick Ctrl+click on a slider opens its text field).
    auto down = [&io](int a, int b) { return io.KeysDown[a] || io.KeysDown[b]; };
    io.KeyCtrl = down(GLFW_KEY_LEFT_CONTROL, GLFW_KEY_RIGHT_CONTROL);
    io.KeyShift = down(GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT);
    io.KeyAlt = down(GLFW_KEY_LEFT_ALT, GLFW_KEY_RIGHT_ALT);
    io.KeySuper = down(GLFW_KEY_LEFT_SUPER, GLFW_KEY_RIGHT_SUPER);
}

}  // namespace fx
