#pragma once
// A mesh in GL buffers with the chapter's attribute locations: 0 position, 1 texture coordinate,
// 2 normal (3 and 4 are joints and weights for skinned meshes).
#include "geometry/mesh_data.hpp"
#include "gl/object.hpp"

namespace fx {

// Vertex attribute locations (the Shader effects chapter's location map).
namespace attribute_location {
inline constexpr GLuint position = 0;  // vec3
inline constexpr GLuint texcoord = 1;  // vec2
inline constexpr GLuint normal = 2;    // vec3
inline constexpr GLuint joints = 3;    // uvec4, skinned meshes
inline constexpr GLuint weights = 4;   // vec4, skinned meshes
}  // namespace attribute_location

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
