#include "gl/framebuffer.hpp"

#include <vector>

#include "base/log.hpp"

namespace fx::gl {

Framebuffer::Framebuffer(std::string_view label) : name_(createFramebuffer(label)), label_(label) {}

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

Status checkFramebufferComplete(GLuint framebuffer, std::string_view label) {
    GLenum status = glCheckNamedFramebufferStatus(framebuffer, GL_DRAW_FRAMEBUFFER);
    if (status == GL_FRAMEBUFFER_COMPLETE) return Status::success();
    return Error{cat(framebufferStatusName(status), " on ", label)};
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
