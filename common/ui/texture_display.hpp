#pragma once
// Float and depth textures cannot go to ImGui as they are: a value of 40 or a depth of 0.9997 says
// nothing on screen. TextureDisplay renders one level of a texture through shaders/ui/
// texture_view.frag (range, exposure, channels, view transform, depth linearisation, NaN / Inf /
// negative marks) into a DisplaySurface, an RGBA8 texture of exactly the size it is shown at, which
// ImGui then draws like any image.
#include <array>
#include <string>

#include <imgui.h>

#include "gl/framebuffer.hpp"
#include "gl/program.hpp"
#include "gl/texture.hpp"
#include "ui/texture_source.hpp"
#include "ui/view_settings.hpp"

namespace fx {

// Which part of a level lands on the surface: the texel coordinate under the surface's lower-left
// corner and how many texels one surface pixel spans (below 1: zoomed in).
struct ViewWindow {
    double originX = 0.0, originY = 0.0;
    double texelsPerPixel = 1.0;

    // The whole level, centred, as large as fits.
    static ViewWindow fit(Size2D level, int width, int height);
    // The texel under a surface pixel (x, y from the lower-left corner, in pixels).
    double texelX(double pixelX) const { return originX + pixelX * texelsPerPixel; }
    double texelY(double pixelY) const { return originY + pixelY * texelsPerPixel; }
};

class DisplaySurface {
public:
    explicit DisplaySurface(std::string label = "ui.display");

    // Recreates the texture when the size changes (at least 1x1).
    void resize(int width, int height);
    int width() const { return texture_.width(); }
    int height() const { return texture_.height(); }
    const gl::Texture& texture() const { return texture_; }
    GLuint framebuffer() const { return framebuffer_.name(); }
    bool ready() const { return static_cast<bool>(texture_); }

    // For ImGui::Image. Rows are bottom-up in GL, so the v coordinates are flipped.
    ImTextureID id() const;
    static ImVec2 uvTopLeft() { return {0.0f, 1.0f}; }
    static ImVec2 uvBottomRight() { return {1.0f, 0.0f}; }

private:
    std::string label_;
    gl::Texture texture_;
    gl::Framebuffer framebuffer_;
};

class TextureDisplay {
public:
    TextureDisplay();

    bool ok() const { return error_.empty(); }
    const std::string& error() const { return error_; }

    // Draws level settings.level of `source` (which must be alive) into `surface`. GL state is left
    // as it was found.
    void draw(DisplaySurface& surface, const TextureSource& source, const ViewSettings& settings,
              const ViewWindow& window, bool grid = false) const;

private:
    // One program per view transform, built the first time a view uses it. The transform is a
    // #define, not a uniform: llvmpipe runs both sides of a uniform branch, so with a uniform every
    // texel paid for all four transforms (the sRGB encodings' pow() twice). Only Direct is built at once.
    const gl::Program& program(DisplayTransform transform) const;
    mutable std::array<gl::Program, kDisplayTransformCount> programs_;
    mutable std::string error_;
    gl::VertexArrayName vertexArray_;
    gl::SamplerName sampler_;
};

}  // namespace fx
