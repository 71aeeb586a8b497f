#pragma once
// Keys for Dear ImGui that are never lost between two frames. Debian's imgui 1.86 GLFW backend keeps
// a key's state (down or up) and Dear ImGui looks at it once a frame, so a key pressed and released
// between two frames (a slow frame, a quick tap, a scripted xdotool key) is never seen: Enter does not
// leave a text field, which then keeps the keyboard, and the arrows stop changing steps. The latch
// sees every press (its callback runs in front of the backend's) and holds a key that was let go
// down for the one frame that follows, so Dear ImGui sees each press exactly once; a modifier let go
// since the last frame reads as down too, so a quick Ctrl+click stays one. (Dear ImGui 1.87
// queues input events itself; the text typed goes through the character callback and was never lost.)
//
// The mouse buttons likewise: 1.86 reads the cursor where it is when the frame begins, so a click made
// during a slow frame acted on whatever was under the cursor a second later, and two clicks in one
// frame were one. The latch queues each press and release with the cursor where it was at that moment
// and hands Dear ImGui one a frame (as 1.87's queue trickles them), so a click acts on what was under
// the mouse when it was pressed.
struct GLFWwindow;

namespace fx {

class KeyLatch {
public:
    // Call after the GLFW backend installed its callbacks; one window at a time.
    explicit KeyLatch(GLFWwindow* window);
    ~KeyLatch();  // puts the backend's callback back (before the backend shuts down)
    KeyLatch(const KeyLatch&) = delete;
    KeyLatch& operator=(const KeyLatch&) = delete;

    // After the backend's NewFrame, before ImGui::NewFrame: the keys pressed since the last frame
    // read as down this frame; a key held down for ImGui last frame and let go since reads as up; the
    // oldest queued mouse press or release is this frame's, at the cursor position it had then.
    void beforeNewFrame();

private:
    GLFWwindow* window_;
};

}  // namespace fx
