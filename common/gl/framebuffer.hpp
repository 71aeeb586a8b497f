#pragma once
// Framebuffers with names: completeness is checked when attachments change and an incomplete one
// is reported by name ("GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT on bloom.down[3]"), never drawn into.
#include <string>
#include <string_view>

#include "base/result.hpp"
#include "gl/object.hpp"
#include "gl/texture.hpp"

namespace fx::gl {

class Framebuffer {
public:
    Framebuffer() = default;
    explicit Framebuffer(std::string_view label);

    void attachColor(int index, const Texture& texture, int level = 0);
    void attachDepth(const Texture& texture, int level = 0);
    // Which colour attachments the fragment shader's outputs go to, in order.
    void setDrawBuffers(int colorCount);

    // Ok, or the status name and the label.
    Status checkComplete() const;

    GLuint name() const { return name_.name(); }
    const std::string& label() const { return label_; }
    // A framebuffer kept for textures whose names change (a pooled texture's) says what they hold now.
    void relabel(std::string_view label);

private:
    FramebufferName name_;
    std::string label_;
};

// What a window's back buffer is: RGBA8 colour and 24-bit depth at one size, in one framebuffer. The
// headless context presents into one; a window's picture beside the overlay's panels is drawn into
// another (ui/picture_view.cpp).
struct ColorDepthTarget {
    Texture color, depth;
    Framebuffer framebuffer;
    // `label` names the framebuffer; the textures are "<prefix>.color" and "<prefix>.depth".
    static ColorDepthTarget create(int width, int height, std::string_view prefix, std::string_view label);
};

std::string_view framebufferStatusName(GLenum status);
// Complete by glCheckNamedFramebufferStatus, and every entry of its draw-buffer list names an
// attachment that has an image: since GL 4.1 a list naming an empty attachment is "complete" and what
// the fragment shader writes there silently vanishes, so that is an error here, with the entry named.
Status checkFramebufferComplete(GLuint framebuffer, std::string_view label);
// Every output `program` declares reaches an attachment with an image through `framebuffer`'s
// draw-buffer list; otherwise an error naming the output, its location and the framebuffer (GL drops
// such writes without a word).
Status checkProgramOutputs(GLuint program, GLuint framebuffer, std::string_view label);

}  // namespace fx::gl
