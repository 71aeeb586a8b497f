#pragma once
// The lesson's picture in a window: the lesson renders into a target of the picture's own size (or a
// share of it, the frame budget's scale), which is then drawn into its place in the window
// (ui/panel_layout.hpp), beside the overlay's panels and never under them. The same place shows the compare
// view: the previous step's picture, kept when the step changes, against this one, split or as an amplified
// difference (shaders/ui/compare.frag). The same drawing of two pictures serves an exercise's views: the
// student's probe result, the reference's and their difference (app/exercise_session.hpp).
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

// Two pictures in the picture's place: the first alone, split (the first left of a white line, the second
// right of it) or the difference |second - first|.
enum class PairView { First, Split, Difference };

constexpr float kDifferenceGain = 8.0f;

// How two pictures show. Each channel value v (red, green, blue) as v * scale + offset, the difference as
// |second - first| * scale * gain, clamped to [0, 1]; NaN and Inf magenta in every view, so a probe's
// numbers (tap offsets in pixels, metres) show as colours and a bad value stands out. keepAspect: the
// first picture's aspect is kept, scaled up by a whole number where it fits (fitPicture), drawn with
// nearest filtering and centred on a dark ground; else the pictures fill the place.
struct PairDisplay {
    float scale = 1.0f;
    float offset = 0.0f;
    float gain = kDifferenceGain;
    bool keepAspect = false;
};

// Where a picture of `picture`'s size goes in `place` with its aspect kept: the largest whole-number
// multiple of its size that fits (a 1x1 probe a square, a 17x3 a strip), or the largest fraction when it
// is larger than the place; centred, on whole pixels.
LayoutRect fitPicture(Size2D picture, const LayoutRect& place);

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
    // The size the kept picture was rendered at (empty when none is kept).
    Size2D previousSize() const;

    // Draws the picture (or the compare view) into `window` at `place` (top-left origin, window pixels;
    // the window's framebuffer is windowHeight tall). GL state is left as it was found.
    void present(GLuint window, int windowHeight, const LayoutRect& place, CompareMode mode) const;

    // Draws `first` and `second` as `view` into `place` (as present). An empty `first` leaves the place
    // the dark ground (a student's file that did not build has no picture); `second` is used by Split and
    // Difference only. Returns where the pictures went (top-left origin, window pixels).
    LayoutRect drawPair(GLuint window, int windowHeight, const LayoutRect& place, PairView view,
                        const gl::Texture& first, const gl::Texture& second,
                        const PairDisplay& display) const;

    // The picture as the lesson drew it (for picture.png), bottom-up rows.
    ByteImage read() const;
    bool ok() const { return error_.empty(); }
    const std::string& error() const { return error_; }

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
