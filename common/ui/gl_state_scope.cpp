#include "ui/gl_state_scope.hpp"

namespace fx {
namespace {

void setEnabled(GLenum capability, bool on) {
    if (on) {
        glEnable(capability);
    } else {
        glDisable(capability);
    }
}

}  // namespace

GlStateScope::GlStateScope() {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
    glGetIntegerv(GL_VIEWPORT, viewport_);
    glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray_);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture0_);
    glGetIntegerv(GL_SAMPLER_BINDING, &sampler0_);
    glGetIntegerv(GL_PACK_ALIGNMENT, &packAlignment_);
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &unpackAlignment_);
    glGetBooleanv(GL_COLOR_WRITEMASK, colorMask_);
    blend_ = glIsEnabled(GL_BLEND);
    depthTest_ = glIsEnabled(GL_DEPTH_TEST);
    cullFace_ = glIsEnabled(GL_CULL_FACE);
    scissorTest_ = glIsEnabled(GL_SCISSOR_TEST);
    stencilTest_ = glIsEnabled(GL_STENCIL_TEST);
    framebufferSrgb_ = glIsEnabled(GL_FRAMEBUFFER_SRGB);
}

GlStateScope::~GlStateScope() {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawFramebuffer_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(readFramebuffer_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    // A program deleted while it was current stays current until replaced, but cannot be made
    // current again: restore it only while it still exists.
    auto program = static_cast<GLuint>(program_);
    glUseProgram(program != 0 && glIsProgram(program) ? program : 0);
    auto vertexArray = static_cast<GLuint>(vertexArray_);
    glBindVertexArray(vertexArray != 0 && glIsVertexArray(vertexArray) ? vertexArray : 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture0_));
    glBindSampler(0, static_cast<GLuint>(sampler0_));
    glActiveTexture(static_cast<GLenum>(activeTexture_));
    glPixelStorei(GL_PACK_ALIGNMENT, packAlignment_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, unpackAlignment_);
    glColorMask(colorMask_[0], colorMask_[1], colorMask_[2], colorMask_[3]);
    setEnabled(GL_BLEND, blend_);
    setEnabled(GL_DEPTH_TEST, depthTest_);
    setEnabled(GL_CULL_FACE, cullFace_);
    setEnabled(GL_SCISSOR_TEST, scissorTest_);
    setEnabled(GL_STENCIL_TEST, stencilTest_);
    setEnabled(GL_FRAMEBUFFER_SRGB, framebufferSrgb_);
}

void usePlainDrawState() {
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

}  // namespace fx
