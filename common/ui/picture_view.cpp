#include "ui/picture_view.hpp"

#include <algorithm>
#include <cmath>

#include "base/log.hpp"
#include "gl/debug_output.hpp"
#include "gl/readback.hpp"
#include "ui/gl_state_scope.hpp"

namespace fx {
namespace {

// The uniform locations of shaders/ui/compare.frag.
enum Uniform : GLint { kMode = 0, kPicture, kGain, kDisplay, kGround };

// Around a picture that keeps its aspect: the window's dark ground (app/frame_loop.cpp).
constexpr float kGroundColour[3] = {0.08f, 0.08f, 0.09f};

}  // namespace

CompareMode nextCompareMode(CompareMode mode) {
    switch (mode) {
        case CompareMode::Off:
            return CompareMode::Split;
        case CompareMode::Split:
            return CompareMode::Difference;
        case CompareMode::Difference:
            return CompareMode::Off;
    }
    return CompareMode::Off;
}

const char* describeCompareMode(CompareMode mode) {
    switch (mode) {
        case CompareMode::Off:
            return "off";
        case CompareMode::Split:
            return "split: the previous step left of the line, this step right";
        case CompareMode::Difference:
            return "difference with the previous step, x8";
    }
    return "";
}

LayoutRect fitPicture(Size2D picture, const LayoutRect& place) {
    if (picture.empty() || place.width < 1 || place.height < 1) return place;
    const double fit = std::min(double(place.width) / picture.width, double(place.height) / picture.height);
    const double scale = fit >= 1.0 ? std::floor(fit) : fit;
    const float width = std::max(1.0f, float(std::floor(picture.width * scale)));
    const float height = std::max(1.0f, float(std::floor(picture.height * scale)));
    return {place.x + std::floor((place.width - width) / 2),
            place.y + std::floor((place.height - height) / 2), width, height};
}

PictureView::PictureView() {
    auto built = gl::Program::build({"common/fullscreen.vert", "ui/compare.frag", {}, {}, "ui.compare view"});
    if (!built) {
        error_ = built.error();
        log::error("the compare view's shader did not build: ", error_);
    } else {
        program_ = std::move(*built);
    }
    vertexArray_ = gl::createVertexArray("ui.compare view (no vertices)");
}

GLuint PictureView::target(Size2D size) {
    if (size.empty()) return 0;
    if (size == size_ && target_.framebuffer.name()) return target_.framebuffer.name();
    size_ = size;
    target_ = gl::ColorDepthTarget::create(size.width, size.height, "picture",
                                           "picture (the lesson's output in a window)");
    return target_.framebuffer.name();
}

void PictureView::keepAsPrevious(int step) {
    if (!target_.color) return;
    if (!previous_ || previous_.width() != size_.width || previous_.height() != size_.height) {
        previous_ = gl::Texture::create2D(TextureFormat::RGBA8, size_.width, size_.height, 1,
                                          "picture.previous_step");
    }
    gl::DebugGroup group("keep the picture for the compare view");
    glCopyImageSubData(target_.color.name(), GL_TEXTURE_2D, 0, 0, 0, 0, previous_.name(), GL_TEXTURE_2D, 0, 0,
                       0, 0, size_.width, size_.height, 1);
    previousStep_ = step;
}

Size2D PictureView::previousSize() const {
    if (!previous_ || !previousStep_) return {};
    return {previous_.width(), previous_.height()};
}

void PictureView::present(GLuint window, int windowHeight, const LayoutRect& place, CompareMode mode) const {
    if (!target_.framebuffer.name() || place.width < 1 || place.height < 1) return;
    GlStateScope keep;
    // The place in GL's bottom-left window coordinates.
    const int x = int(place.x), width = int(place.width), height = int(place.height);
    const int y = windowHeight - int(place.bottom());
    const bool comparing = mode != CompareMode::Off && previous_ && program_;
    if (!comparing) {
        // The exact pixels the lesson drew when the picture is as large as its place; scaled up smoothly
        // when the frame budget rendered it smaller (app/picture_scale.hpp).
        const bool exact = size_.width == width && size_.height == height;
        glBlitNamedFramebuffer(target_.framebuffer.name(), window, 0, 0, size_.width, size_.height, x, y,
                               x + width, y + height, GL_COLOR_BUFFER_BIT, exact ? GL_NEAREST : GL_LINEAR);
        return;
    }
    (void)drawPair(window, windowHeight, place,
                   mode == CompareMode::Split ? PairView::Split : PairView::Difference, previous_,
                   target_.color, PairDisplay{});
}

LayoutRect PictureView::drawPair(GLuint window, int windowHeight, const LayoutRect& place, PairView view,
                                 const gl::Texture& first, const gl::Texture& second,
                                 const PairDisplay& display) const {
    if (!program_ || place.width < 1 || place.height < 1) return place;
    const LayoutRect picture =
        display.keepAspect && first ? fitPicture({first.width(), first.height()}, place) : place;
    GlStateScope keep;
    gl::DebugGroup group("picture view: two pictures");
    // GL's bottom-left window coordinates: the whole place is drawn (the ground around the picture too).
    const auto glY = [&](const LayoutRect& r) { return float(windowHeight) - r.bottom(); };
    const GLuint p = program_.name();
    // An empty first picture: every pixel is outside the (empty) picture, so the place is all ground.
    const float pictureWidth = first ? picture.width : 0.0f;
    glProgramUniform1i(p, kMode, view == PairView::First ? 0 : view == PairView::Split ? 1 : 2);
    glProgramUniform4f(p, kPicture, picture.x, glY(picture), pictureWidth, picture.height);
    glProgramUniform1f(p, kGain, display.gain);
    glProgramUniform2f(p, kDisplay, display.scale, display.offset);
    glProgramUniform3fv(p, kGround, 1, kGroundColour);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, window);
    glViewport(int(place.x), int(glY(place)), int(place.width), int(place.height));
    usePlainDrawState();
    glUseProgram(p);
    glBindVertexArray(vertexArray_.name());
    // Both units always hold a texture: the second is the first where the view does not use it.
    const GLuint firstName = first ? first.name() : target_.color.name();
    glBindTextureUnit(0, firstName);
    glBindTextureUnit(1, second ? second.name() : firstName);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTextureUnit(1, 0);
    return picture;
}

ByteImage PictureView::read() const {
    if (!target_.framebuffer.name()) return {};
    return gl::readFramebufferRgba8(target_.framebuffer.name(), size_.width, size_.height);
}

}  // namespace fx
