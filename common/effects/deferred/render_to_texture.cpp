#include "effects/deferred/render_to_texture.hpp"

#include <algorithm>

#include "base/log.hpp"
#include "effects/deferred/lecture_mrt.hpp"
#include "effects/scene/camera_matrices.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "render_gl/program_pass.hpp"

namespace fx {
namespace {

std::string internalFormatName(GLint format) {
    switch (format) {
        case GL_RGBA8:
            return "RGBA8";
        case GL_RGBA16F:
            return "RGBA16F";
        case GL_RGBA32F:
            return "RGBA32F";
        case GL_RG16F:
            return "RG16F";
        case GL_DEPTH_COMPONENT24:
            return "GL_DEPTH_COMPONENT24";
        case GL_DEPTH_COMPONENT32F:
            return "Depth32F";
        default:
            return cat("internal format ", format);
    }
}

std::string describeOne(GLuint fbo, GLenum attachment) {
    GLint type = GL_NONE, name = 0;
    glGetNamedFramebufferAttachmentParameteriv(fbo, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type == GL_NONE) return {};
    glGetNamedFramebufferAttachmentParameteriv(fbo, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
    GLint width = 0, height = 0, format = 0;
    if (type == GL_RENDERBUFFER) {
        glGetNamedRenderbufferParameteriv(GLuint(name), GL_RENDERBUFFER_WIDTH, &width);
        glGetNamedRenderbufferParameteriv(GLuint(name), GL_RENDERBUFFER_HEIGHT, &height);
        glGetNamedRenderbufferParameteriv(GLuint(name), GL_RENDERBUFFER_INTERNAL_FORMAT, &format);
        return cat("renderbuffer ", internalFormatName(format), " ", width, "x", height);
    }
    glGetTextureLevelParameteriv(GLuint(name), 0, GL_TEXTURE_WIDTH, &width);
    glGetTextureLevelParameteriv(GLuint(name), 0, GL_TEXTURE_HEIGHT, &height);
    glGetTextureLevelParameteriv(GLuint(name), 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    char label[128] = {};
    GLsizei length = 0;
    glGetObjectLabel(GL_TEXTURE, GLuint(name), sizeof label, &length, label);
    return cat("texture ", std::string(label, std::size_t(length)), " ", internalFormatName(format), " ",
               width, "x", height);
}

}  // namespace

std::string describeAttachments(GLuint fbo) {
    std::string text;
    for (int i = 0; i < 8; ++i) {
        std::string one = describeOne(fbo, GL_COLOR_ATTACHMENT0 + GLenum(i));
        if (!one.empty()) text += cat(text.empty() ? "" : "; ", "colour ", i, ": ", one);
    }
    std::string depth = describeOne(fbo, GL_DEPTH_ATTACHMENT);
    text += cat(text.empty() ? "" : "; ", "depth: ", depth.empty() ? "none" : depth);
    return text;
}

RenderToTexture::RenderToTexture() {
    glNamedRenderbufferStorage(depthRenderbuffer_.name(), GL_DEPTH_COMPONENT24, kRttSize, kRttSize);

    withRenderbuffer_.attachColor(0, color_);
    glNamedFramebufferRenderbuffer(withRenderbuffer_.name(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                   depthRenderbuffer_.name());
    withRenderbuffer_.setDrawBuffers(1);

    withTexture_.attachColor(0, color_);
    withTexture_.attachDepth(depthTexture_);
    withTexture_.setDrawBuffers(1);
    for (const gl::Framebuffer* fbo : {&withRenderbuffer_, &withTexture_}) {
        if (Status s = fbo->checkComplete(); !s) log::error(s.error());
    }
}

GLuint RenderToTexture::framebuffer(RttDepth depth) const {
    return depth == RttDepth::texture ? withTexture_.name() : withRenderbuffer_.name();
}

std::string RenderToTexture::attachmentsText(RttDepth depth) const {
    return describeAttachments(framebuffer(depth));
}

TextureHandle RenderToTexture::declare(FrameGraph& graph, const World& world, RttDepth depth) const {
    TextureHandle color = graph.importTexture("rtt.color", color_.spec(), color_.name());
    const gl::ReloadableProgram* program = &program_;
    const GLuint fbo = framebuffer(depth);
    Pass& pass = graph.addPass("render to texture", [program, fbo, world](PassContext&) {
        const Scene& scene = world.scene();
        // The graph bound a framebuffer for rtt.color; the recipe's own one (with its depth) replaces it.
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glViewport(0, 0, kRttSize, kRttSize);  // at most the FBO's size, whatever the window's
        // The sky, as the scene pass clears to it (an RGBA8 target clips it to [0, 1] anyway).
        const float sky[4] = {std::clamp(scene.background.r, 0.0f, 1.0f),
                              std::clamp(scene.background.g, 0.0f, 1.0f),
                              std::clamp(scene.background.b, 0.0f, 1.0f), 1.0f};
        const float far = 1.0f;
        glClearNamedFramebufferfv(fbo, GL_COLOR, 0, sky);
        glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &far);
        CameraMatrices camera = cameraMatrices(scene.camera, kRttSize, kRttSize);
        SceneMeshes::setFrameUniforms(program->name(), scene, camera);
        setLectureLight(program->name());
        world.draw(program->name());
    });
    pass.writeColor(color);
    if (depth == RttDepth::texture) {
        // Imported too, so the inspector can show it; the pass writes it through its own framebuffer.
        TextureHandle d = graph.importTexture("rtt.depth", depthTexture_.spec(), depthTexture_.name());
        pass.writeDepth(d);
    }
    PassState state = hdrSceneState(world.scene());
    state.clearColor.reset();  // cleared in the body, on the recipe's framebuffer
    state.clearDepth.reset();
    runsWith(pass.setState(state).setTaps(2), program_);  // base colour and emissive textures (phong.frag)
    return color;
}

}  // namespace fx
