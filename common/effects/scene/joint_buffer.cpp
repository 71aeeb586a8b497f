#include "effects/scene/joint_buffer.hpp"

#include <string>

namespace fx {

void JointMatrixBuffer::upload(std::span<const glm::mat4> matrices) {
    count_ = matrices.size();
    if (count_ == 0) return;
    if (count_ > capacity_) {
        // Immutable storage cannot grow: make a new buffer, with room to spare.
        capacity_ = count_ + count_ / 2;
        buffer_ = gl::createBuffer(label_);
        glNamedBufferStorage(buffer_.name(), static_cast<GLsizeiptr>(capacity_ * sizeof(glm::mat4)), nullptr,
                             GL_DYNAMIC_STORAGE_BIT);
    }
    glNamedBufferSubData(buffer_.name(), 0, static_cast<GLsizeiptr>(count_ * sizeof(glm::mat4)),
                         matrices.data());
}

void JointMatrixBuffer::bind(GLuint binding) const {
    if (count_ == 0 || !buffer_) return;
    glBindBufferRange(GL_SHADER_STORAGE_BUFFER, binding, buffer_.name(), 0,
                      static_cast<GLsizeiptr>(count_ * sizeof(glm::mat4)));
}

}  // namespace fx
