#pragma once
// A skinned mesh on the GPU, in two forms:
//   source: the bind-pose vertices with their joints and weights, attributes 0 position, 1 texcoord,
//           2 normal, 3 joints (uvec4), 4 weights (vec4): what a skinning vertex shader reads;
//   posed:  the same vertices after skinning (attributes 0, 1, 2 only), written by GpuSkinning with
//           transform feedback. Any program that draws a GpuMesh draws the posed mesh, so the shadow
//           pass, the lit pass and a debug view all see one pose computed once per frame.
#include <span>

#include "effects/scene/gpu_mesh.hpp"
#include "geometry/mesh_data.hpp"
#include "scene/skin.hpp"

namespace fx {

// The posed vertex as transform feedback writes it (and as GpuMesh lays out its vertices).
struct PosedVertex {
    float position[3];
    float texcoord[2];
    float normal[3];
};
static_assert(sizeof(PosedVertex) == 32);

class SkinnedMesh {
public:
    SkinnedMesh() = default;
    // `influences` has one entry per vertex.
    SkinnedMesh(const MeshData& mesh, std::span<const JointInfluence> influences, std::string_view label);

    // Draws the posed vertices (after GpuSkinning::pose) with whatever program is in use.
    void drawPosed() const;
    // Draws the bind-pose source with its joints and weights, for a program that skins in its vertex
    // shader (with the joint matrices bound at binding 0).
    void drawSource() const;

    GLuint sourceVertexArray() const { return sourceVao_.name(); }
    GLuint posedBuffer() const { return posed_.name(); }
    GLsizei vertexCount() const { return vertexCount_; }
    GLsizei indexCount() const { return indexCount_; }
    // Vertices whose weights add up to (almost) nothing: they keep their bind pose.
    std::size_t unweightedVertices() const { return unweighted_; }
    // Joint indices the mesh uses with a weight above 0 (largest + 1).
    std::size_t jointsUsed() const { return jointsUsed_; }

private:
    gl::VertexArrayName sourceVao_, posedVao_;
    gl::BufferName source_, posed_, indices_;
    GLsizei vertexCount_ = 0, indexCount_ = 0;
    std::size_t unweighted_ = 0;
    std::size_t jointsUsed_ = 0;
};

}  // namespace fx
