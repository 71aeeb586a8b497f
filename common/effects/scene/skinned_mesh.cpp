#include "effects/scene/skinned_mesh.hpp"

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace fx {
namespace {

struct SourceVertex {
    float position[3];
    float texcoord[2];
    float normal[3];
    std::uint16_t joints[4];
    float weights[4];
};

}  // namespace

SkinnedMesh::SkinnedMesh(const MeshData& mesh, std::span<const JointInfluence> influences,
                         std::string_view label)
    : sourceVao_(gl::createVertexArray(std::string(label) + ".source")),
      posedVao_(gl::createVertexArray(std::string(label) + ".posed")),
      source_(gl::createBuffer(std::string(label) + ".source vertices")),
      posed_(gl::createBuffer(std::string(label) + ".posed vertices")),
      indices_(gl::createBuffer(std::string(label) + ".indices")),
      vertexCount_(static_cast<GLsizei>(mesh.positions.size())),
      indexCount_(static_cast<GLsizei>(mesh.indices.size())) {
    if (mesh.positions.empty() || mesh.indices.empty()) {  // zero-size storage is a GL error
        vertexCount_ = indexCount_ = 0;
        return;
    }
    std::vector<SourceVertex> vertices(mesh.positions.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        SourceVertex& v = vertices[i];
        const glm::vec3& p = mesh.positions[i];
        glm::vec2 uv = i < mesh.uvs.size() ? mesh.uvs[i] : glm::vec2(0.0f);
        glm::vec3 n = i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0.0f, 1.0f, 0.0f);
        v = {{p.x, p.y, p.z}, {uv.x, uv.y}, {n.x, n.y, n.z}, {0, 0, 0, 0}, {0, 0, 0, 0}};
        if (i < influences.size()) {
            const JointInfluence& inf = influences[i];
            float total = 0.0f;
            for (int c = 0; c < 4; ++c) {
                v.joints[c] = inf.joints[c];
                v.weights[c] = inf.weights[c];
                if (inf.weights[c] > 0.0f) {
                    total += inf.weights[c];
                    jointsUsed_ = std::max<std::size_t>(jointsUsed_, std::size_t(inf.joints[c]) + 1);
                }
            }
            if (!(total > kMinTotalWeight)) ++unweighted_;
        } else {
            ++unweighted_;
        }
    }
    glNamedBufferStorage(source_.name(), static_cast<GLsizeiptr>(vertices.size() * sizeof(SourceVertex)),
                         vertices.data(), 0);
    // The posed copy starts as the bind pose, so drawing before the first pose shows something sane.
    std::vector<PosedVertex> posed(vertices.size());
    for (std::size_t i = 0; i < posed.size(); ++i) {
        const SourceVertex& s = vertices[i];
        posed[i] = {{s.position[0], s.position[1], s.position[2]},
                    {s.texcoord[0], s.texcoord[1]},
                    {s.normal[0], s.normal[1], s.normal[2]}};
    }
    glNamedBufferStorage(posed_.name(), static_cast<GLsizeiptr>(posed.size() * sizeof(PosedVertex)),
                         posed.data(), 0);
    glNamedBufferStorage(indices_.name(),
                         static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
                         mesh.indices.data(), 0);

    namespace loc = attribute_location;
    GLuint src = sourceVao_.name();
    glVertexArrayVertexBuffer(src, 0, source_.name(), 0, sizeof(SourceVertex));
    glVertexArrayElementBuffer(src, indices_.name());
    auto floatAttribute = [](GLuint vao, GLuint location, GLint size, GLuint offset) {
        glEnableVertexArrayAttrib(vao, location);
        glVertexArrayAttribFormat(vao, location, size, GL_FLOAT, GL_FALSE, offset);
        glVertexArrayAttribBinding(vao, location, 0);
    };
    floatAttribute(src, loc::position, 3, offsetof(SourceVertex, position));
    floatAttribute(src, loc::texcoord, 2, offsetof(SourceVertex, texcoord));
    floatAttribute(src, loc::normal, 3, offsetof(SourceVertex, normal));
    // Joint indices stay integers (uvec4 in the shader): the I variant, no conversion to float.
    glEnableVertexArrayAttrib(src, loc::joints);
    glVertexArrayAttribIFormat(src, loc::joints, 4, GL_UNSIGNED_SHORT, offsetof(SourceVertex, joints));
    glVertexArrayAttribBinding(src, loc::joints, 0);
    floatAttribute(src, loc::weights, 4, offsetof(SourceVertex, weights));

    GLuint dst = posedVao_.name();
    glVertexArrayVertexBuffer(dst, 0, posed_.name(), 0, sizeof(PosedVertex));
    glVertexArrayElementBuffer(dst, indices_.name());
    floatAttribute(dst, loc::position, 3, offsetof(PosedVertex, position));
    floatAttribute(dst, loc::texcoord, 2, offsetof(PosedVertex, texcoord));
    floatAttribute(dst, loc::normal, 3, offsetof(PosedVertex, normal));
}

void SkinnedMesh::drawPosed() const {
    if (indexCount_ == 0) return;
    glBindVertexArray(posedVao_.name());
    glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
}

void SkinnedMesh::drawSource() const {
    if (indexCount_ == 0) return;
    glBindVertexArray(sourceVao_.name());
    glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
}

}  // namespace fx
