#include "gl/object.hpp"

#include <algorithm>

namespace fx::gl {

void labelObject(GLenum identifier, GLuint name, std::string_view label) {
    GLint maxLength = 0;
    glGetIntegerv(GL_MAX_LABEL_LENGTH, &maxLength);
    auto length = static_cast<GLsizei>(std::min<std::size_t>(label.size(), std::max(0, maxLength - 1)));
    glObjectLabel(identifier, name, length, label.data());
}

TextureName createTexture(GLenum target, std::string_view label) {
    GLuint n = 0;
    glCreateTextures(target, 1, &n);
    TextureName t(n);
    t.label(label);
    return t;
}

BufferName createBuffer(std::string_view label) {
    GLuint n = 0;
    glCreateBuffers(1, &n);
    BufferName b(n);
    b.label(label);
    return b;
}

FramebufferName createFramebuffer(std::string_view label) {
    GLuint n = 0;
    glCreateFramebuffers(1, &n);
    FramebufferName f(n);
    f.label(label);
    return f;
}

RenderbufferName createRenderbuffer(std::string_view label) {
    GLuint n = 0;
    glCreateRenderbuffers(1, &n);
    RenderbufferName r(n);
    r.label(label);
    return r;
}

VertexArrayName createVertexArray(std::string_view label) {
    GLuint n = 0;
    glCreateVertexArrays(1, &n);
    VertexArrayName v(n);
    v.label(label);
    return v;
}

SamplerName createSampler(std::string_view label) {
    GLuint n = 0;
    glCreateSamplers(1, &n);
    SamplerName s(n);
    s.label(label);
    return s;
}

QueryName createQuery(GLenum target, std::string_view label) {
    GLuint n = 0;
    glCreateQueries(target, 1, &n);
    QueryName q(n);
    q.label(label);
    return q;
}

}  // namespace fx::gl
