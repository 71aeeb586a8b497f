#include "gl/framebuffer.hpp"

#include <vector>

#include "base/log.hpp"

namespace fx::gl {

Framebuffer::Framebuffer(std::string_view label) : name_(createFramebuffer(label)), label_(label) {}

void Framebuffer::relabel(std::string_view label) {
    if (label == label_) return;
    label_ = std::string(label);
    name_.label(label);
}

void Framebuffer::attachColor(int index, const Texture& texture, int level) {
    glNamedFramebufferTexture(name(), GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(index), texture.name(),
                              level);
}

void Framebuffer::attachDepth(const Texture& texture, int level) {
    GLenum attachment = hasStencil(texture.spec().format) ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT;
    glNamedFramebufferTexture(name(), attachment, texture.name(), level);
}

void Framebuffer::setDrawBuffers(int colorCount) {
    if (colorCount == 0) {
        glNamedFramebufferDrawBuffer(name(), GL_NONE);
        glNamedFramebufferReadBuffer(name(), GL_NONE);
        return;
    }
    std::vector<GLenum> buffers;
    for (int i = 0; i < colorCount; ++i) buffers.push_back(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i));
    glNamedFramebufferDrawBuffers(name(), colorCount, buffers.data());
    glNamedFramebufferReadBuffer(name(), GL_COLOR_ATTACHMENT0);
}

Status Framebuffer::checkComplete() const {
    return checkFramebufferComplete(name(), label_);
}

std::string_view framebufferStatusName(GLenum status) {
    switch (status) {
        case GL_FRAMEBUFFER_COMPLETE:
            return "GL_FRAMEBUFFER_COMPLETE";
        case GL_FRAMEBUFFER_UNDEFINED:
            return "GL_FRAMEBUFFER_UNDEFINED";
        case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
            return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
            return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER:
            return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
        case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER:
            return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
        case GL_FRAMEBUFFER_UNSUPPORTED:
            return "GL_FRAMEBUFFER_UNSUPPORTED";
        case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE:
            return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
        case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS:
            return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
        default:
            return "unknown framebuffer status";
    }
}

namespace {

// The attachment draw buffer `i` of `framebuffer` names, or GL_NONE.
// (Bound for the query and put back: not every driver answers GL_DRAW_BUFFERi for a named framebuffer.)
GLenum drawBuffer(GLuint framebuffer, int i) {
    GLint previous = 0, buffer = GL_NONE;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    if (GLuint(previous) != framebuffer) glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    glGetIntegerv(GL_DRAW_BUFFER0 + static_cast<GLenum>(i), &buffer);
    if (GLuint(previous) != framebuffer) glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(previous));
    return static_cast<GLenum>(buffer);
}

bool hasImage(GLuint framebuffer, GLenum attachment) {
    GLint type = GL_NONE;
    glGetNamedFramebufferAttachmentParameteriv(framebuffer, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
                                               &type);
    return type != GL_NONE;
}

int maxDrawBuffers() {
    GLint n = 8;
    glGetIntegerv(GL_MAX_DRAW_BUFFERS, &n);
    return n;
}

}  // namespace

Status checkFramebufferComplete(GLuint framebuffer, std::string_view label) {
    GLenum status = glCheckNamedFramebufferStatus(framebuffer, GL_DRAW_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) return Error{cat(framebufferStatusName(status), " on ", label)};
    if (framebuffer == 0) return Status::success();
    for (int i = 0, n = maxDrawBuffers(); i < n; ++i) {
        GLenum buffer = drawBuffer(framebuffer, i);
        if (buffer == GL_NONE || hasImage(framebuffer, buffer)) continue;
        return Error{
            cat("draw buffer ", i, " of ", label, " names GL_COLOR_ATTACHMENT", buffer - GL_COLOR_ATTACHMENT0,
                ", which has no image attached: what the shader writes to location ", i, " would be lost")};
    }
    return Status::success();
}

Status checkProgramOutputs(GLuint program, GLuint framebuffer, std::string_view label) {
    GLint outputs = 0;
    glGetProgramInterfaceiv(program, GL_PROGRAM_OUTPUT, GL_ACTIVE_RESOURCES, &outputs);
    for (GLint k = 0; k < outputs; ++k) {
        const GLenum property = GL_LOCATION;
        GLint location = -1;
        glGetProgramResourceiv(program, GL_PROGRAM_OUTPUT, GLuint(k), 1, &property, 1, nullptr, &location);
        if (location < 0) continue;  // a built-in such as gl_FragDepth
        char name[128] = {};
        GLsizei length = 0;
        glGetProgramResourceName(program, GL_PROGRAM_OUTPUT, GLuint(k), sizeof name, &length, name);
        std::string output(name, std::size_t(length));
        if (framebuffer == 0) {
            if (location == 0) continue;
            return Error{cat("output '", output, "' (location ", location,
                             ") has no buffer in the window's framebuffer ", label, ": its writes are lost")};
        }
        GLenum buffer = location < maxDrawBuffers() ? drawBuffer(framebuffer, location) : GL_NONE;
        if (buffer == GL_NONE)
            return Error{cat("output '", output, "' (location ", location,
                             ") has no entry in the draw-buffer list of ", label, ": its writes are lost")};
        if (!hasImage(framebuffer, buffer))
            return Error{cat("output '", output, "' (location ", location, ") goes to GL_COLOR_ATTACHMENT",
                             buffer - GL_COLOR_ATTACHMENT0, " of ", label,
                             ", which has no image: its writes are lost")};
    }
    return Status::success();
}

ColorDepthTarget ColorDepthTarget::create(int width, int height, std::string_view prefix,
                                          std::string_view label) {
    ColorDepthTarget t;
    t.color = Texture::create2D(TextureFormat::RGBA8, width, height, 1, std::string(prefix) + ".color");
    t.depth = Texture::create2D(TextureFormat::Depth24, width, height, 1, std::string(prefix) + ".depth");
    t.framebuffer = Framebuffer(label);
    t.framebuffer.attachColor(0, t.color);
    t.framebuffer.attachDepth(t.depth);
    t.framebuffer.setDrawBuffers(1);
    if (auto status = t.framebuffer.checkComplete(); !status) log::error(status.error());
    return t;
}

}  // namespace fx::gl
