#pragma once
// Move-only owners of GL names. Each kind of name has a small traits struct that says how to
// delete it and which namespace glObjectLabel uses for it.
#include <string>
#include <string_view>
#include <utility>

#include "gl/context_guard.hpp"
#include "gl/gl.hpp"

namespace fx::gl {

// Gives a GL name a label that debuggers and KHR_debug messages show.
void labelObject(GLenum identifier, GLuint name, std::string_view label);
// The object's label as GL has it (empty when it has none).
std::string objectLabel(GLenum identifier, GLuint name);

template <class Traits>
class Object {
public:
    Object() = default;
    explicit Object(GLuint name) : name_(name) {}
    ~Object() { reset(); }
    Object(const Object&) = delete;
    Object& operator=(const Object&) = delete;
    Object(Object&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    Object& operator=(Object&& other) noexcept {
        if (this != &other) {
            reset();
            name_ = std::exchange(other.name_, 0);
        }
        return *this;
    }

    GLuint name() const { return name_; }
    explicit operator bool() const { return name_ != 0; }

    void reset() {
        if (name_ == 0) return;
        if (contextAlive()) {
            Traits::destroy(name_);
        } else {
            noteOrphanedName(Traits::kind);
        }
        name_ = 0;
    }

    void label(std::string_view text) const {
        if (name_ != 0) labelObject(Traits::labelNamespace, name_, text);
    }

private:
    GLuint name_ = 0;
};

struct TextureTraits {
    static constexpr const char* kind = "texture";
    static constexpr GLenum labelNamespace = GL_TEXTURE;
    static void destroy(GLuint n) { glDeleteTextures(1, &n); }
};
struct BufferTraits {
    static constexpr const char* kind = "buffer";
    static constexpr GLenum labelNamespace = GL_BUFFER;
    static void destroy(GLuint n) { glDeleteBuffers(1, &n); }
};
struct FramebufferTraits {
    static constexpr const char* kind = "framebuffer";
    static constexpr GLenum labelNamespace = GL_FRAMEBUFFER;
    static void destroy(GLuint n) { glDeleteFramebuffers(1, &n); }
};
struct RenderbufferTraits {
    static constexpr const char* kind = "renderbuffer";
    static constexpr GLenum labelNamespace = GL_RENDERBUFFER;
    static void destroy(GLuint n) { glDeleteRenderbuffers(1, &n); }
};
struct VertexArrayTraits {
    static constexpr const char* kind = "vertex array";
    static constexpr GLenum labelNamespace = GL_VERTEX_ARRAY;
    static void destroy(GLuint n) { glDeleteVertexArrays(1, &n); }
};
struct SamplerTraits {
    static constexpr const char* kind = "sampler";
    static constexpr GLenum labelNamespace = GL_SAMPLER;
    static void destroy(GLuint n) { glDeleteSamplers(1, &n); }
};
struct QueryTraits {
    static constexpr const char* kind = "query";
    static constexpr GLenum labelNamespace = GL_QUERY;
    static void destroy(GLuint n) { glDeleteQueries(1, &n); }
};
struct ShaderTraits {
    static constexpr const char* kind = "shader";
    static constexpr GLenum labelNamespace = GL_SHADER;
    static void destroy(GLuint n) { glDeleteShader(n); }
};
struct ProgramTraits {
    static constexpr const char* kind = "program";
    static constexpr GLenum labelNamespace = GL_PROGRAM;
    static void destroy(GLuint n) { glDeleteProgram(n); }
};

using BufferName = Object<BufferTraits>;
using FramebufferName = Object<FramebufferTraits>;
using RenderbufferName = Object<RenderbufferTraits>;
using VertexArrayName = Object<VertexArrayTraits>;
using SamplerName = Object<SamplerTraits>;
using QueryName = Object<QueryTraits>;
using ShaderName = Object<ShaderTraits>;
using ProgramName = Object<ProgramTraits>;
using TextureName = Object<TextureTraits>;

// Creation with a label in one step (DSA: the name exists as an object at once).
TextureName createTexture(GLenum target, std::string_view label);
BufferName createBuffer(std::string_view label);
FramebufferName createFramebuffer(std::string_view label);
RenderbufferName createRenderbuffer(std::string_view label);
VertexArrayName createVertexArray(std::string_view label);
SamplerName createSampler(std::string_view label);
// Bilinear filtering, clamped to the edge on both axes: what a post effect's taps need whatever
// parameters the texture it reads carries (REPEAT would bring in the opposite edge).
SamplerName createLinearClampSampler(std::string_view label);
QueryName createQuery(GLenum target, std::string_view label);

}  // namespace fx::gl
