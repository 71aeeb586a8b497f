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
    bool pictureScale = false, measure = false;  // the frame budget's scale; the cost panel's sweep
    bool nextLesson = false, previousLesson = false;
    bool renderdoc = false;  // a frame in RenderDoc (app/renderdoc_session.hpp)
    bool quit = false;       // Esc: quits, or cancels the cost panel's sweep while one runs (FrameLoop)
    // Not keys of the app: a mouse button went down, Enter or Esc was pressed (either may open or close
    // one of the overlay's text fields, which decides whose the other keys are: FrameLoop::takeKeys).
    bool clicked = false, enterOrEscape = false;

    KeyPresses& operator|=(const KeyPresses& o);
    bool any() const;
    bool overlaps(const KeyPresses& o) const;  // a key (or a click) pressed in both
};

// The keys a text field being edited uses itself (arrows, space, ".", "+", "-", Esc), moved out of
// `keys` into the result; the F keys and Page Up/Down stay in `keys`.
KeyPresses takeTextFieldKeys(KeyPresses& keys);

// The keys of a lesson window and what each does, for --help and the overlay's Keys tab. The same
// table decides what a press does, so the help and the window cannot disagree.
struct WindowKeyHelp {
    std::string key, action;
    std::string token;  // the name --press takes ("space", "F2", "pagedown")
};
std::vector<WindowKeyHelp> windowKeysHelp();
// The name of the key that sets `press` ("F6"), as the screen writes it.
std::string windowKeyName(bool KeyPresses::*press);

// The press of the key --press names by its token; nothing when no key has that token.
std::optional<KeyPresses> keyPressNamed(std::string_view token);

class WindowInput {
public:
    // window == nullptr (headless): no keys, no pointer.
    explicit WindowInput(GLFWwindow* window);
    ~WindowInput();
    WindowInput(const WindowInput&) = delete;
    WindowInput& operator=(const WindowInput&) = delete;

    // The presses for this frame, in the order they came: every press is queued, and a frame takes
    // them up to a second press of a key it already has (three F6 presses during one slow frame are
    // three frames' presses, not one) or up to a key whose effect the next frame must show (a step
    // change, F3, F12...); the rest wait for the frames that follow.
    KeyPresses takeKeyPresses();
    // Presses still queued for later frames.
    std::size_t waiting() const;
    // The mouse in the picture's pixels, bottom-left origin. The picture is drawn into `placeX`,
    // `placeY` (from the top-left, framebuffer pixels) at `place`'s size, scaled from `picture` (the
    // size it was rendered at: the frame budget's scale); the pointer is present only over it.
    Pointer pointer(Size2D framebuffer, int placeX, int placeY, Size2D place, Size2D picture,
                    bool overUi) const;

private:
    GLFWwindow* window_;
};

}  // namespace fx
