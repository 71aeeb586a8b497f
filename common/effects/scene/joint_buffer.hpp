#pragma once
// The joint matrices of one skinned object in a shader storage buffer: std430, an array of mat4 that
// shaders/common/skinning.glsl reads at binding glsl::kJointMatricesBinding (the chapter's JointDataBlock).
// An SSBO belongs to the context, not to a program: once bound, every program that declares the block sees
// it.
#include <span>
#include <string>
#include <string_view>

#include <glm/mat4x4.hpp>

#include "effects/scene/scene_bindings.hpp"
#include "gl/object.hpp"

namespace fx {

class JointMatrixBuffer {
public:
    JointMatrixBuffer() = default;
    explicit JointMatrixBuffer(std::string_view label) : label_(label) {}

    // Replaces the contents; grows the buffer when there are more joints than it holds.
    void upload(std::span<const glm::mat4> matrices);
    // Binds exactly the uploaded joints to `binding`, so jointMatrices.length() in the shader is
    // the joint count (the shader ignores joint indices beyond it).
    void bind(GLuint binding = glsl::kJointMatricesBinding) const;

    std::size_t jointCount() const { return count_; }
    GLuint name() const { return buffer_.name(); }

private:
    std::string label_ = "joint matrices";
    gl::BufferName buffer_;
    std::size_t capacity_ = 0;
    std::size_t count_ = 0;
};

}  // namespace fx
