#pragma once
// The keys and the mouse of a lesson window. Create it before the overlay: Dear ImGui's GLFW
// backend chains the key callback that was installed before it, so both see every key.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/lesson.hpp"
#include "platform/context.hpp"

struct GLFWwindow;

namespace fx {

struct KeyPresses {
    bool next = false, previous = false, toggleOverlay = false, reload = false, screenshot = false;
    bool pause = false, advanceFrame = false;      // the clock
    bool textBigger = false, textSmaller = false;  // the overlay's text scale
    bool resetLayout = false, compare = false, findSpecial = false;
    bool nextLesson = false, previousLesson = false;
    bool quit = false;
    bool cancel = false;  // Esc while something long is under way (setEscapeCancels)

    KeyPresses& operator|=(const KeyPresses& o);
};

// The keys of a lesson window and what each does, for --help and the overlay's Keys tab. The same
// table decides what a press does, so the help and the window cannot disagree.
struct WindowKeyHelp {
    std::string key, action;
    std::string token;  // the name --press takes ("space", "F2", "pagedown")
};
std::vector<WindowKeyHelp> windowKeysHelp();

// The press of the key --press names by its token; nothing when no key has that token.
std::optional<KeyPresses> keyPressNamed(std::string_view token);

class WindowInput {
public:
    // window == nullptr (headless): no keys, no pointer.
    explicit WindowInput(GLFWwindow* window);
    ~WindowInput();
    WindowInput(const WindowInput&) = delete;
    WindowInput& operator=(const WindowInput&) = delete;

    // The presses since the last call.
    KeyPresses takeKeyPresses();
    // While on, Esc cancels what is under way (the cost panel's sweep) instead of quitting.
    void setEscapeCancels(bool on);
    // The mouse in the picture's pixels, bottom-left origin. `picture` is the picture's place in the
    // framebuffer (x, y from the top-left, in framebuffer pixels); the pointer is present only over it.
    Pointer pointer(Size2D framebuffer, int pictureX, int pictureY, Size2D picture, bool overUi) const;

private:
    GLFWwindow* window_;
};

}  // namespace fx
