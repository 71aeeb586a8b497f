#pragma once
// The lesson's picture in a window: the lesson renders into a target of the picture's own size (or a
// share of it, the frame budget's scale), which is then drawn into its place in the window
// (ui/panel_layout.hpp), beside the overlay's panels and never under them. The same place shows the compare
// view: the previous step's picture, kept when the step changes, against this one, split or as an amplified
// difference (shaders/ui/compare.frag).
#include <optional>

#include "base/size2d.hpp"
#include "gl/framebuffer.hpp"
#include "gl/object.hpp"
#include "gl/program.hpp"
#include "gl/texture.hpp"
#include "image/image.hpp"
#include "ui/panel_layout.hpp"

namespace fx {

enum class CompareMode { Off, Split, Difference };
CompareMode nextCompareMode(CompareMode mode);  // off -> split -> difference -> off
const char* describeCompareMode(CompareMode mode);

class PictureView {
public:
    PictureView();

    // The framebuffer the lesson draws into this frame: RGBA8 colour and 24-bit depth at `size` (made
    // again when the size changes, like a window's back buffer).
    GLuint target(Size2D size);
    Size2D size() const { return size_; }

    // Keeps the picture now in the target as the previous step's (call when the step changes, before
    // the new step renders). `step` is 0-based.
    void keepAsPrevious(int step);
    std::optional<int> previousStep() const { return previousStep_; }

    // Draws the picture (or the compare view) into `window` at `place` (top-left origin, window pixels;
    // the window's framebuffer is windowHeight tall). GL state is left as it was found.
    void present(GLuint window, int windowHeight, const LayoutRect& place, CompareMode mode) const;

    // The picture as the lesson drew it (for picture.png), bottom-up rows.
    ByteImage read() const;
    bool ok() const { return error_.empty(); }
    const std::string& error() const { return error_; }

    static constexpr float kDifferenceGain = 8.0f;

private:
    Size2D size_;
    gl::ColorDepthTarget target_;
    gl::Texture previous_;
    std::optional<int> previousStep_;
    gl::Program program_;
    gl::VertexArrayName vertexArray_;
    std::string error_;
};

}  // namespace fx
