#include "gl/object.hpp"

#include <algorithm>

namespace fx::gl {

void labelObject(GLenum identifier, GLuint name, std::string_view label) {
    GLint maxLength = 0;
    glGetIntegerv(GL_MAX_LABEL_LENGTH, &maxLength);
    auto length = static_cast<GLsizei>(std::min<std::size_t>(label.size(), std::max(0, maxLength - 1)));
    glObjectLabel(identifier, name, length, label.data());
}

std::string objectLabel(GLenum identifier, GLuint name) {
    GLint maxLength = 0;
    glGetIntegerv(GL_MAX_LABEL_LENGTH, &maxLength);
    std::string label(std::size_t(std::max(maxLength, 1)), '\0');
    GLsizei length = 0;
    glGetObjectLabel(identifier, name, GLsizei(label.size()), &length, label.data());
    label.resize(std::size_t(std::max(length, 0)));
    return label;
}

namespace {

// Every owner is made the same way: a DSA create call for one name, then its label.
template <class Owner, class Create>
Owner createLabelled(Create create, std::string_view label) {
    GLuint name = 0;
    create(&name);
    Owner owner(name);
    owner.label(label);
    return owner;
}

}  // namespace

TextureName createTexture(GLenum target, std::string_view label) {
    return createLabelled<TextureName>([target](GLuint* n) { glCreateTextures(target, 1, n); }, label);
}

BufferName createBuffer(std::string_view label) {
    return createLabelled<BufferName>([](GLuint* n) { glCreateBuffers(1, n); }, label);
}

FramebufferName createFramebuffer(std::string_view label) {
    return createLabelled<FramebufferName>([](GLuint* n) { glCreateFramebuffers(1, n); }, label);
}

RenderbufferName createRenderbuffer(std::string_view label) {
    return createLabelled<RenderbufferName>([](GLuint* n) { glCreateRenderbuffers(1, n); }, label);
}

VertexArrayName createVertexArray(std::string_view label) {
    return createLabelled<VertexArrayName>([](GLuint* n) { glCreateVertexArrays(1, n); }, label);
}

SamplerName createSampler(std::string_view label) {
    return createLabelled<SamplerName>([](GLuint* n) { glCreateSamplers(1, n); }, label);
}

SamplerName createLinearClampSampler(std::string_view label) {
    SamplerName sampler = createSampler(label);
    GLuint name = sampler.name();
    glSamplerParameteri(name, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glSamplerParameteri(name, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(name, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(name, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return sampler;
}

QueryName createQuery(GLenum target, std::string_view label) {
    return createLabelled<QueryName>([target](GLuint* n) { glCreateQueries(target, 1, n); }, label);
}

}  // namespace fx::gl
