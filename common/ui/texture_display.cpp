#include "ui/texture_display.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "base/log.hpp"
#include "gl/debug_output.hpp"
#include "gl/gl_formats.hpp"
#include "ui/gl_state_scope.hpp"

namespace fx {
namespace {

// The uniform locations of shaders/ui/texture_view.frag.
enum Uniform : GLint {
    kLevel = 0,
    kLevelSize,
    kOrigin,
    kTexelsPerPixel,
    kChannelCount,
    kShown,
    kRange,
    kExposure,
    kLinearDepth = 9,  // location 8 was the transform: now each program's VIEW_TRANSFORM
    kNearFar,
    kHighlight,
    kGrid,
};

}  // namespace

ViewWindow ViewWindow::fit(Size2D level, int width, int height) {
    ViewWindow w;
    if (level.empty() || width <= 0 || height <= 0) return w;
    w.texelsPerPixel = std::max(double(level.width) / width, double(level.height) / height);
    w.originX = level.width / 2.0 - width / 2.0 * w.texelsPerPixel;
    w.originY = level.height / 2.0 - height / 2.0 * w.texelsPerPixel;
    return w;
}

DisplaySurface::DisplaySurface(std::string label) : label_(std::move(label)) {}

void DisplaySurface::resize(int width, int height) {
    width = std::max(width, 1);
    height = std::max(height, 1);
    if (texture_ && texture_.width() == width && texture_.height() == height) return;
    texture_ = gl::Texture::create2D(TextureFormat::RGBA8, width, height, 1, label_);
    glTextureParameteri(texture_.name(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(texture_.name(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    if (!framebuffer_.name()) framebuffer_ = gl::Framebuffer(label_);
    framebuffer_.attachColor(0, texture_);
    framebuffer_.setDrawBuffers(1);
}

ImTextureID DisplaySurface::id() const {
    return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture_.name()));
}

TextureDisplay::TextureDisplay() {
    if (!program(DisplayTransform::Direct)) return;
    vertexArray_ = gl::createVertexArray("ui.texture view (no vertices)");
    // texelFetch ignores filtering, but a depth texture set up for shadow comparisons would
    // compare instead of returning depth: the sampler object turns that off.
    sampler_ = gl::createSampler("ui.texture view sampler");
    glSamplerParameteri(sampler_.name(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(sampler_.name(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(sampler_.name(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
}

const gl::Program& TextureDisplay::program(DisplayTransform transform) const {
    const int index = std::clamp(static_cast<int>(transform), 0, kDisplayTransformCount - 1);
    gl::Program& p = programs_[std::size_t(index)];
    if (p || !error_.empty()) return p;  // built, or the shader is broken: the first error stays
    auto built = gl::Program::build({"common/fullscreen.vert",
                                     "ui/texture_view.frag",
                                     {},
                                     cat("#define VIEW_TRANSFORM ", index, "\n"),
                                     cat("ui.texture view (", toString(transform), ")")});
    if (!built) {
        error_ = built.error();
        log::error("the inspector's view shader did not build: ", error_);
        return p;
    }
    p = std::move(*built);
    return p;
}

void TextureDisplay::draw(DisplaySurface& surface, const TextureSource& source, const ViewSettings& s,
                          const ViewWindow& window, bool grid) const {
    if (!ok() || !surface.ready() || !source.alive()) return;
    gl::DebugGroup group(cat("inspector view of ", source.name.empty() ? "a texture" : source.name));
    GlStateScope keep;
    const int level = std::clamp(s.level, 0, source.levels() - 1);
    const Size2D size = source.levelSize(level);
    const GLuint p = program(s.transform).name();
    if (!p) return;
    glProgramUniform1i(p, kLevel, level);
    glProgramUniform2i(p, kLevelSize, size.width, size.height);
    glProgramUniform2f(p, kOrigin, float(window.originX), float(window.originY));
    glProgramUniform1f(p, kTexelsPerPixel, float(std::max(window.texelsPerPixel, 1e-6)));
    glProgramUniform1i(p, kChannelCount, readbackChannelCount(source.spec.format));
    glProgramUniform4f(p, kShown, s.channels[0] ? 1.0f : 0.0f, s.channels[1] ? 1.0f : 0.0f,
                       s.channels[2] ? 1.0f : 0.0f, s.channels[3] ? 1.0f : 0.0f);
    glProgramUniform2f(p, kRange, s.rangeLow, s.rangeHigh);
    glProgramUniform1f(p, kExposure, std::exp2(s.exposureStops));
    glProgramUniform1i(p, kLinearDepth, showsLinearDepth(s, source.spec) ? 1 : 0);
    glProgramUniform2f(p, kNearFar, s.cameraNear, s.cameraFar);
    glProgramUniform1i(p, kHighlight, s.highlightSpecial ? 1 : 0);
    glProgramUniform1i(p, kGrid, grid ? 1 : 0);

    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, surface.framebuffer());
    glViewport(0, 0, surface.width(), surface.height());
    usePlainDrawState();
    glUseProgram(p);
    glBindVertexArray(vertexArray_.name());
    glBindTextureUnit(0, source.native);
    glBindSampler(0, sampler_.name());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace fx
