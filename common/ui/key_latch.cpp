#include "ui/key_latch.hpp"

#include <vector>

#include <imgui.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace fx {
namespace {

// GLFW callbacks are plain functions: the one overlay window's presses go here.
GLFWkeyfun backendCallback = nullptr;
std::vector<int> pressedSinceFrame;
std::vector<int> heldForImGui;  // forced down for the frame that just began

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

}  // namespace

KeyLatch::KeyLatch(GLFWwindow* window) : window_(window) {
    pressedSinceFrame.clear();
    heldForImGui.clear();
    backendCallback = glfwSetKeyCallback(window_, onKey);
}

KeyLatch::~KeyLatch() {
    glfwSetKeyCallback(window_, backendCallback);
    backendCallback = nullptr;
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
    // The backend sets the modifiers from the keys in its callback; a Ctrl held for ImGui counts too
    // (a quick Ctrl+click on a slider opens its text field).
    auto down = [&io](int a, int b) { return io.KeysDown[a] || io.KeysDown[b]; };
    io.KeyCtrl = down(GLFW_KEY_LEFT_CONTROL, GLFW_KEY_RIGHT_CONTROL);
    io.KeyShift = down(GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT);
    io.KeyAlt = down(GLFW_KEY_LEFT_ALT, GLFW_KEY_RIGHT_ALT);
    io.KeySuper = down(GLFW_KEY_LEFT_SUPER, GLFW_KEY_RIGHT_SUPER);
}

}  // namespace fx
