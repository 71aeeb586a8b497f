#include "app/window_input.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <deque>
#include <utility>

namespace fx {
namespace {

struct WindowKey {
    int key;            // GLFW_KEY_*
    int alternate;      // another key that does the same (the keypad's + and -), or 0
    const char* name;   // as --help and the Keys tab show it
    const char* token;  // as --press takes it
    const char* action;
    bool KeyPresses::*press;  // what a press sets
};

constexpr WindowKey kWindowKeys[] = {
    {GLFW_KEY_LEFT, 0, "left arrow", "left", "previous step", &KeyPresses::previous},
    {GLFW_KEY_RIGHT, 0, "right arrow", "right", "next step", &KeyPresses::next},
    {GLFW_KEY_PAGE_UP, 0, "Page Up", "pageup", "previous lesson (same window size and flags)",
     &KeyPresses::previousLesson},
    {GLFW_KEY_PAGE_DOWN, 0, "Page Down", "pagedown", "next lesson (same window size and flags)",
     &KeyPresses::nextLesson},
    {GLFW_KEY_SPACE, 0, "space", "space", "pause or resume the clock", &KeyPresses::pause},
    {GLFW_KEY_PERIOD, 0, ".", "period", "one frame forward (pauses the clock)", &KeyPresses::advanceFrame},
    {GLFW_KEY_F3, 0, "F3", "F3",
     "compare with the previous step: split, difference x8, off (an exercise's step: yours, reference, "
     "difference)",
     &KeyPresses::compare},
    {GLFW_KEY_F4, 0, "F4", "F4", "inspector: go to the next NaN or Inf texel and pin the probe",
     &KeyPresses::findSpecial},
    {GLFW_KEY_F6, 0, "F6", "F6",
     "picture scale: automatic (within the frame budget), 100%, 50%, 25% (also --picture-scale)",
     &KeyPresses::pictureScale},
    {GLFW_KEY_F7, 0, "F7", "F7",
     "measure the cost of the quality knobs (the Cost of quality tab; Esc cancels)", &KeyPresses::measure},
    {GLFW_KEY_EQUAL, GLFW_KEY_KP_ADD, "+", "plus", "larger text (kept for the next start)",
     &KeyPresses::textBigger},
    {GLFW_KEY_MINUS, GLFW_KEY_KP_SUBTRACT, "-", "minus", "smaller text", &KeyPresses::textSmaller},
    {GLFW_KEY_F2, 0, "F2", "F2", "reset the layout (panels to their places, text size kept)",
     &KeyPresses::resetLayout},
    {GLFW_KEY_F1, 0, "F1", "F1", "show or hide the overlay", &KeyPresses::toggleOverlay},
    {GLFW_KEY_F5, 0, "F5", "F5", "reload shaders (they also reload when saved)", &KeyPresses::reload},
    {GLFW_KEY_F12, 0, "F12", "F12", "save a screenshot to out/ (named by lesson and step, never replaced)",
     &KeyPresses::screenshot},
    {GLFW_KEY_F9, 0, "F9", "F9",
     "capture the next frame in RenderDoc (a run started with --renderdoc FILE.rdc)", &KeyPresses::renderdoc},
    {GLFW_KEY_ESCAPE, 0, "Esc", "Esc", "quit (while the cost panel measures: cancel the measure)",
     &KeyPresses::quit},
};

// GLFW callbacks are plain functions: the presses of the one lesson window go here, one entry a press
// in the order they came (a slow frame must not fold three presses of F6 into one).
std::deque<KeyPresses>* pending = nullptr;
std::deque<KeyPresses> queued;
// More than a person presses during any frame; a stuck key repeating cannot grow the queue past it.
constexpr std::size_t kMostQueued = 256;

void enqueue(const KeyPresses& press) {
    if (pending && pending->size() < kMostQueued) pending->push_back(press);
}

void onKey(GLFWwindow*, int key, int, int action, int mods) {
    if (action != GLFW_PRESS || !pending) return;
    KeyPresses press;
    if (key == GLFW_KEY_ENTER || key == GLFW_KEY_KP_ENTER || key == GLFW_KEY_ESCAPE)
        press.enterOrEscape = true;
    // Ctrl/Alt/Super chords are someone else's (the window manager's, ImGui's text fields').
    if (!(mods & (GLFW_MOD_CONTROL | GLFW_MOD_ALT | GLFW_MOD_SUPER))) {
        // Shift+= is "+" on most layouts; the key is the same.
        for (const WindowKey& k : kWindowKeys) {
            if (k.key != key && (k.alternate == 0 || k.alternate != key)) continue;
            press.*k.press = true;
        }
    }
    if (press.any()) enqueue(press);
}

void onMouseButton(GLFWwindow*, int, int action, int) {
    if (action != GLFW_PRESS) return;
    KeyPresses press;
    press.clicked = true;
    enqueue(press);
}

// Keys whose effect the next frame must show before another key acts: the step, the lesson, the
// compare view, the overlay, a screenshot, quitting.
bool endsABatch(const KeyPresses& p) {
    return p.next || p.previous || p.nextLesson || p.previousLesson || p.compare || p.toggleOverlay ||
           p.screenshot || p.quit;
}

}  // namespace

bool KeyPresses::any() const {
    for (const WindowKey& k : kWindowKeys) {
        if (this->*k.press) return true;
    }
    return clicked || enterOrEscape;
}

bool KeyPresses::overlaps(const KeyPresses& o) const {
    for (const WindowKey& k : kWindowKeys) {
        if (this->*k.press && o.*k.press) return true;
    }
    return (clicked && o.clicked) || (enterOrEscape && o.enterOrEscape);
}

KeyPresses& KeyPresses::operator|=(const KeyPresses& o) {
    for (const WindowKey& k : kWindowKeys) this->*k.press = this->*k.press || o.*k.press;
    clicked = clicked || o.clicked;
    enterOrEscape = enterOrEscape || o.enterOrEscape;
    return *this;
}

KeyPresses takeTextFieldKeys(KeyPresses& keys) {
    KeyPresses field;
    for (bool KeyPresses::*press :
         {&KeyPresses::next, &KeyPresses::previous, &KeyPresses::pause, &KeyPresses::advanceFrame,
          &KeyPresses::textBigger, &KeyPresses::textSmaller, &KeyPresses::quit})
        field.*press = std::exchange(keys.*press, false);
    return field;
}

std::vector<WindowKeyHelp> windowKeysHelp() {
    std::vector<WindowKeyHelp> keys;
    for (const WindowKey& k : kWindowKeys) keys.push_back({k.name, k.action, k.token});
    return keys;
}

std::string windowKeyName(bool KeyPresses::*press) {
    for (const WindowKey& k : kWindowKeys) {
        if (k.press == press) return k.name;
    }
    return "?";
}

std::optional<KeyPresses> keyPressNamed(std::string_view token) {
    for (const WindowKey& k : kWindowKeys) {
        if (token != k.token) continue;
        KeyPresses p;
        p.*k.press = true;
        return p;
    }
    return std::nullopt;
}

WindowInput::WindowInput(GLFWwindow* window) : window_(window) {
    if (!window_) return;
    queued.clear();
    pending = &queued;
    glfwSetKeyCallback(window_, onKey);
    glfwSetMouseButtonCallback(window_, onMouseButton);
}

WindowInput::~WindowInput() {
    if (window_) pending = nullptr;
}

KeyPresses WindowInput::takeKeyPresses() {
    KeyPresses batch;
    if (!window_) return batch;
    while (!queued.empty() && !batch.overlaps(queued.front())) {
        const KeyPresses press = queued.front();
        queued.pop_front();
        batch |= press;
        if (endsABatch(press)) break;
    }
    return batch;
}

std::size_t WindowInput::waiting() const {
    return window_ ? queued.size() : 0;
}

Pointer WindowInput::pointer(Size2D framebuffer, int placeX, int placeY, Size2D place, Size2D picture,
                             bool overUi) const {
    Pointer p;
    if (!window_ || framebuffer.empty() || picture.empty() || place.empty()) return p;
    double x = 0, y = 0;
    glfwGetCursorPos(window_, &x, &y);
    int windowWidth = 0, windowHeight = 0;
    glfwGetWindowSize(window_, &windowWidth, &windowHeight);
    if (windowWidth <= 0 || windowHeight <= 0) return p;
    // Window coordinates (top-left origin, screen units) to the place's pixels, then to the picture's
    // (bottom-left origin), which may be smaller than its place.
    double sx = double(framebuffer.width) / windowWidth, sy = double(framebuffer.height) / windowHeight;
    const double px = (x * sx - placeX) * picture.width / place.width;
    const double py = (y * sy - placeY) * picture.height / place.height;
    p.x = float(px);
    p.y = float(picture.height - py);
    p.present = px >= 0 && py >= 0 && px < picture.width && py < picture.height;
    p.leftDown = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    p.overUi = overUi;
    return p;
}

}  // namespace fx
