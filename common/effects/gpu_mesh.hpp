#pragma once
// A mesh in GL buffers with the chapter's attribute locations: 0 position, 1 texture coordinate,
// 2 normal (3 and 4 are joints and weights for skinned meshes).
#include "geometry/mesh_data.hpp"
#include "gl/object.hpp"

namespace fx {

class GpuMesh {
public:
    GpuMesh() = default;
    GpuMesh(const MeshData& data, std::string_view label);

    void draw(GLsizei instances = 1) const;
    GLsizei indexCount() const { return indexCount_; }
    std::size_t vertexCount() const { return vertexCount_; }
    GLuint vertexArray() const { return vao_.name(); }

private:
    gl::VertexArrayName vao_;
    gl::BufferName vertices_, indices_;
    GLsizei indexCount_ = 0;
    std::size_t vertexCount_ = 0;
};

}  // namespace fx
