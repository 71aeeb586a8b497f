#include "effects/dof/framebuffer_mistakes.hpp"

#include "gl/framebuffer.hpp"

namespace fx {

FramebufferCheck checkIncompleteFramebuffer(IncompleteFramebuffer kind) {
    if (kind == IncompleteFramebuffer::none) return {};
    gl::FramebufferName framebuffer = gl::createFramebuffer("fbo.incomplete (made so on purpose)");
    gl::TextureName texture;
    if (kind == IncompleteFramebuffer::nonRenderableColor) {
        // RGB9_E5: a texture format every GL 4.5 samples, and none has to render to (not colour-renderable).
        texture = gl::createTexture(GL_TEXTURE_2D, "fbo.incomplete colour (RGB9_E5)");
        glTextureStorage2D(texture.name(), 1, GL_RGB9_E5, 16, 16);
        glNamedFramebufferTexture(framebuffer.name(), GL_COLOR_ATTACHMENT0, texture.name(), 0);
    }
    // noAttachment: nothing attached and no default size: GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT.
    const GLenum status = glCheckNamedFramebufferStatus(framebuffer.name(), GL_DRAW_FRAMEBUFFER);
    Status checked = gl::checkFramebufferComplete(framebuffer.name(), "fbo.incomplete");
    return {std::string(gl::framebufferStatusName(status)),
            checked.ok() ? std::string("complete") : checked.error()};
}

SamplingMistakes::SamplingMistakes() : compare_(gl::createSampler("fbo depth, COMPARE_MODE on")) {
    glSamplerParameteri(compare_.name(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glSamplerParameteri(compare_.name(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glSamplerParameteri(compare_.name(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(compare_.name(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

TextureHandle SamplingMistakes::declare(FrameGraph& graph, TextureHandle color, TextureHandle depth,
                                        ShownTarget shown, Size2D size) {
    if (shown == ShownTarget::color || size.width < 1 || size.height < 1) return color;
    const TextureDesc shownDesc{TextureSize::output(), TextureFormat::RGBA16F, 1};
    if (shown == ShownTarget::depth || shown == ShownTarget::depthCompareMode) {
        const FullscreenPass* program = &depth_;
        const GLuint sampler = shown == ShownTarget::depthCompareMode ? compare_.name() : 0;
        Pass& pass = depth_.addPass(graph, "fbo depth shown", [program, depth, sampler](PassContext& ctx) {
            glBindSampler(0, sampler);
            program->draw({ctx.native(depth)});
            glBindSampler(0, 0);  // unit 0 goes back to its textures' own parameters
        });
        pass.read(depth).setTaps(1);
        return pass.create("fbo.shown", shownDesc, TextureUsage::ColorAttachment);
    }
    // The student's render target: glTexImage2D makes level 0 only, and MIN_FILTER keeps its default,
    // GL_NEAREST_MIPMAP_LINEAR, which asks for levels that do not exist. Rendering into it works;
    // sampling it reads an incomplete texture: (0, 0, 0, 1).
    if (!rawTarget_ || rawSize_ != size) {
        rawTarget_ = gl::createTexture(GL_TEXTURE_2D, "fbo.raw_target (glTexImage2D, level 0 only)");
        GLint previous = 0;
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
        glBindTexture(GL_TEXTURE_2D, rawTarget_.name());
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, size.width, size.height, 0, GL_RGBA, GL_HALF_FLOAT,
                     nullptr);
        glBindTexture(GL_TEXTURE_2D, GLuint(previous));
        rawSize_ = size;
    }
    TextureHandle raw =
        graph.importTexture("fbo.raw_target", {size.width, size.height, TextureFormat::RGBA16F, 1},
                            rawTarget_.name(), TextureSize::output());
    const FullscreenPass* copy = &copy_;
    Pass& into = copy_.addPass(graph, "fbo copy into the raw target",
                               [copy, color](PassContext& ctx) { copy->draw({ctx.native(color)}); });
    into.read(color).writeColor(raw).setTaps(1);
    Pass& out = copy_.addPass(graph, "fbo raw target shown",
                              [copy, raw](PassContext& ctx) { copy->draw({ctx.native(raw)}); });
    out.read(raw).setTaps(1);
    return out.create("fbo.shown", shownDesc, TextureUsage::ColorAttachment);
}

}  // namespace fx
