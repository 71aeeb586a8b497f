#include "effects/scene/gpu_skinning.hpp"

#include "base/log.hpp"
#include "gl/debug_output.hpp"

namespace fx {

GpuSkinning::GpuSkinning() {
    GLuint feedback = 0;
    glCreateTransformFeedbacks(1, &feedback);
    feedback_ = gl::Object<TransformFeedbackTraits>(feedback);
    feedback_.label("skinning.feedback");
    glNamedFramebufferParameteri(framebuffer_.name(), GL_FRAMEBUFFER_DEFAULT_WIDTH, 1);
    glNamedFramebufferParameteri(framebuffer_.name(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, 1);
}

void GpuSkinning::pose(const SkinnedMesh& mesh, const JointMatrixBuffer& joints) const {
    if (!program_.usable() || mesh.vertexCount() == 0) return;
    // Lessons pose their meshes before the frame's passes run, outside the graph's groups.
    gl::DebugGroup group("skinning (transform feedback)");
    GLint previousFeedback = 0, previousFramebuffer = 0;
    glGetIntegerv(GL_TRANSFORM_FEEDBACK_BINDING, &previousFeedback);
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousFramebuffer);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.name());
    GLboolean discardWasOn = glIsEnabled(GL_RASTERIZER_DISCARD);

    joints.bind(glsl::kJointMatricesBinding);
    glTransformFeedbackBufferBase(feedback_.name(), 0, mesh.posedBuffer());
    glUseProgram(program_.name());
    glBindVertexArray(mesh.sourceVertexArray());
    glEnable(GL_RASTERIZER_DISCARD);
    glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, feedback_.name());
    // One point per vertex: transform feedback writes them in order, so output i is vertex i.
    glBeginTransformFeedback(GL_POINTS);
    glDrawArrays(GL_POINTS, 0, mesh.vertexCount());
    glEndTransformFeedback();
    glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, static_cast<GLuint>(previousFeedback));
    if (!discardWasOn) glDisable(GL_RASTERIZER_DISCARD);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(previousFramebuffer));
    // Detach the posed buffer: a buffer bound for transform feedback cannot also be read as vertices.
    glTransformFeedbackBufferBase(feedback_.name(), 0, 0);
    ++posed_;
}

}  // namespace fx
