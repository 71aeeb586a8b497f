#include "ui/picture_view.hpp"

#include <cmath>

#include "base/log.hpp"
#include "gl/debug_output.hpp"
#include "gl/readback.hpp"
#include "ui/gl_state_scope.hpp"

namespace fx {
namespace {

// The uniform locations of shaders/ui/compare.frag.
enum Uniform : GLint { kMode = 0, kPlace, kGain };

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
    const GLuint p = program_.name();
    glProgramUniform1i(p, kMode, mode == CompareMode::Split ? 1 : 2);
    glProgramUniform4f(p, kPlace, float(x), float(y), float(width), float(height));
    glProgramUniform1f(p, kGain, kDifferenceGain);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, window);
    glViewport(x, y, width, height);
    usePlainDrawState();
    glUseProgram(p);
    glBindVertexArray(vertexArray_.name());
    glBindTextureUnit(0, target_.color.name());
    glBindTextureUnit(1, previous_.name());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTextureUnit(1, 0);
}

ByteImage PictureView::read() const {
    if (!target_.framebuffer.name()) return {};
    return gl::readFramebufferRgba8(target_.framebuffer.name(), size_.width, size_.height);
}

}  // namespace fx
