#include "effects/scene/gpu_mesh.hpp"

#include <string>
#include <vector>

namespace fx {
namespace {

struct Vertex {
    float position[3];
    float uv[2];
    float normal[3];
};

}  // namespace

GpuMesh::GpuMesh(const MeshData& data, std::string_view label)
    : vao_(gl::createVertexArray(label)),
      vertices_(gl::createBuffer(std::string(label) + ".vertices")),
      indices_(gl::createBuffer(std::string(label) + ".indices")),
      indexCount_(static_cast<GLsizei>(data.indices.size())),
      vertexCount_(data.positions.size()) {
    if (data.positions.empty() || data.indices.empty()) {  // zero-size storage is a GL error
        indexCount_ = 0;
        vertexCount_ = 0;
        return;
    }
    std::vector<Vertex> vertices(data.positions.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        glm::vec2 uv = i < data.uvs.size() ? data.uvs[i] : glm::vec2(0.0f);
        glm::vec3 n = i < data.normals.size() ? data.normals[i] : glm::vec3(0.0f, 1.0f, 0.0f);
        vertices[i] = {
            {data.positions[i].x, data.positions[i].y, data.positions[i].z}, {uv.x, uv.y}, {n.x, n.y, n.z}};
    }
    glNamedBufferStorage(vertices_.name(), static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
                         vertices.data(), 0);
    glNamedBufferStorage(indices_.name(),
                         static_cast<GLsizeiptr>(data.indices.size() * sizeof(std::uint32_t)),
                         data.indices.data(), 0);
    glVertexArrayVertexBuffer(vao_.name(), 0, vertices_.name(), 0, sizeof(Vertex));
    glVertexArrayElementBuffer(vao_.name(), indices_.name());
    const struct {
        GLuint location;
        GLint size;
        GLuint offset;
    } attributes[] = {
        {0, 3, offsetof(Vertex, position)}, {1, 2, offsetof(Vertex, uv)}, {2, 3, offsetof(Vertex, normal)}};
    for (auto& a : attributes) {
        glEnableVertexArrayAttrib(vao_.name(), a.location);
        glVertexArrayAttribFormat(vao_.name(), a.location, a.size, GL_FLOAT, GL_FALSE, a.offset);
        glVertexArrayAttribBinding(vao_.name(), a.location, 0);
    }
}

void GpuMesh::draw(GLsizei instances) const {
    if (indexCount_ == 0) return;
    glBindVertexArray(vao_.name());
    glDrawElementsInstanced(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr, instances);
}

}  // namespace fx
