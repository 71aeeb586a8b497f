#pragma once
// Skinning on the GPU with transform feedback: a vertex-only program (shaders/effects/skinning/
// pose.vert) reads a SkinnedMesh's source attributes (joints at location 3, weights at 4) and the joint
// matrices from the SSBO at binding 0, and writes each skinned vertex into the mesh's posed buffer.
// The rasteriser is switched off meanwhile; nothing is drawn. The blend follows blendJoints()
// (scene/skin.hpp) exactly: renormalised weights, joints beyond the buffer ignored, the bind pose
// for a vertex without weight. It can run anywhere in a frame: it binds its own (empty) framebuffer and
// puts back the one it found.
#include "effects/scene/joint_buffer.hpp"
#include "effects/scene/skinned_mesh.hpp"
#include "gl/program.hpp"

namespace fx {

class GpuSkinning {
public:
    // Builds the program (it joins the run's registry like any other: its error is shown, and F5
    // rebuilds it).
    GpuSkinning();

    // Writes the posed vertices of `mesh` for the joint matrices in `joints`; nothing while the
    // program has never built (the mesh keeps its bind pose). Leaves the GL state as it found it,
    // except for the program and vertex array bindings (which every draw sets anyway).
    void pose(const SkinnedMesh& mesh, const JointMatrixBuffer& joints) const;

    // Meshes posed so far, for the overlay and tests.
    std::uint64_t posedMeshes() const { return posed_; }

private:
    struct TransformFeedbackTraits {
        static constexpr const char* kind = "transform feedback";
        static constexpr GLenum labelNamespace = GL_TRANSFORM_FEEDBACK;
        static void destroy(GLuint n) { glDeleteTransformFeedbacks(1, &n); }
    };
    gl::ReloadableProgram program_{{"effects/scene/pose.vert", {}, {}, {}, "skinning (transform feedback)"}};
    gl::Object<TransformFeedbackTraits> feedback_;
    // Draw calls need a complete framebuffer even with the rasteriser off, and the one bound may not
    // be (a surfaceless context's default framebuffer): skinning draws into this attachment-less one.
    gl::FramebufferName framebuffer_ = gl::createFramebuffer("skinning.no attachments");
    mutable std::uint64_t posed_ = 0;
};

}  // namespace fx
