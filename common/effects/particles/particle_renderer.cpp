#include "effects/particles/particle_renderer.hpp"

#include <algorithm>

#include <glm/gtc/type_ptr.hpp>

#include "base/log.hpp"
#include "effects/particles/particles_bindings.hpp"
#include "effects/scene/scene_bindings.hpp"
#include "gl/debug_output.hpp"
#include "gl/texture_image.hpp"

namespace fx {
namespace {

constexpr const char* kSourceNames[] = {"instanced", "live list", "one per draw"};

bool softFade(const ParticleDrawSettings& s) {
    return s.softDistance > 0.0f && s.sceneDepth != 0;
}

// A buffer of at least `bytes`, replaced (with `label`) when too small.
void ensureBuffer(gl::BufferName& buffer, std::uint64_t& capacity, std::uint64_t bytes, const char* label) {
    bytes = std::max<std::uint64_t>(bytes, 64);
    if (buffer && capacity >= bytes) return;
    capacity = std::max(bytes, capacity * 2);
    buffer = gl::createBuffer(label);
    glNamedBufferStorage(buffer.name(), GLsizeiptr(capacity), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

}  // namespace

ParticleRenderer::ParticleRenderer()
    : noVertices_(gl::createVertexArray("particles.no_vertices")),
      dot_(gl::Texture::create2D(TextureFormat::RGBA8, 1, 1, 1, "particles.no_sprite")) {
    const unsigned char white[4] = {255, 255, 255, 255};
    glTextureSubImage2D(dot_.name(), 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);
    (void)program(Source::uniforms, ParticleDrawSettings{});  // the chapter's: shows a broken shader now
}

const gl::ReloadableProgram& ParticleRenderer::program(Source source, const ParticleDrawSettings& s) const {
    const int sourceNumber = static_cast<int>(source);
    const bool soft = softFade(s);
    std::optional<gl::ReloadableProgram>& slot =
        programs_[sourceNumber * 4 + (soft ? 2 : 0) + (s.premultiplied ? 1 : 0)];
    if (!slot) {
        slot.emplace(gl::ProgramSources{
            "effects/particles/particle.vert",
            "effects/particles/particle.frag",
            {},
            cat("#define PARTICLE_SOURCE ", sourceNumber, "\n#define PARTICLE_SOFT ", soft ? 1 : 0,
                "\n#define PARTICLE_PREMULTIPLIED ", s.premultiplied ? 1 : 0, "\n"),
            cat("particles: sprites (", kSourceNames[sourceNumber], soft ? ", soft" : "",
                s.premultiplied ? ", premultiplied" : ", straight", ")")});
    }
    return *slot;
}

int ParticleRenderer::programsBuilt() const {
    int built = 0;
    for (const auto& slot : programs_) built += slot ? 1 : 0;
    return built;
}

Status ParticleRenderer::loadSprite(const std::filesystem::path& path, SpriteRows rows) {
    auto image = gl::readTextureImage(path);
    if (!image) return Error{cat("particle sprite ", path.string(), ": ", image.error())};
    // readPng gives the rows bottom-up, GL's order. A decoder that gives the file's order (top row
    // first), uploaded as it comes, puts the picture's top at v = 0: lesson 07's flip_sprite shows it.
    if (rows == SpriteRows::topFirst) {
        const std::size_t stride = std::size_t(image->width) * std::size_t(image->channels);
        auto row = [&](int y) { return image->texels.begin() + std::ptrdiff_t(std::size_t(y) * stride); };
        for (int y = 0; y < image->height / 2; ++y)
            std::swap_ranges(row(y), row(y + 1), row(image->height - 1 - y));
    }
    // Only alpha is used, so a linear format; mipmaps for the small far particles.
    gl::DebugGroup group("upload particles.sprite");
    sprite_ = gl::Texture::create2D(TextureFormat::RGBA8, image->width, image->height,
                                    fullMipChainLength(image->width, image->height), "particles.sprite");
    glTextureSubImage2D(sprite_.name(), 0, 0, 0, image->width, image->height, GL_RGBA, GL_UNSIGNED_BYTE,
                        image->texels.data());
    glGenerateTextureMipmap(sprite_.name());
    glTextureParameteri(sprite_.name(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(sprite_.name(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(sprite_.name(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return Status::success();
}

void ParticleRenderer::setEmitters(const std::vector<GpuEmitter>& emitters) {
    std::size_t bytes = std::max<std::size_t>(emitters.size(), 1) * sizeof(GpuEmitter);
    if (!emitters_ || emitterBytes_ < bytes) {
        emitters_ = gl::createBuffer("particles.emitters");
        glNamedBufferStorage(emitters_.name(), GLsizeiptr(bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
        emitterBytes_ = bytes;
    }
    if (!emitters.empty())
        glNamedBufferSubData(emitters_.name(), 0, GLsizeiptr(emitters.size() * sizeof(GpuEmitter)),
                             emitters.data());
}

// The locations are particles_bindings.glsl's. The one-particle uniforms exist only in the program that
// draws from uniforms, the fade's only in the programs that fade: GL refuses a location the program does
// not have, so each is set only where the program has it.
bool ParticleRenderer::bind(const gl::ReloadableProgram& program, const ParticleDrawSettings& s) const {
    if (!program.usable() || !emitters_) return false;
    const GLuint p = program.name();
    glProgramUniformMatrix4fv(p, glsl::kParticleViewLocation, 1, GL_FALSE, glm::value_ptr(s.view));
    glProgramUniformMatrix4fv(p, glsl::kParticleProjectionLocation, 1, GL_FALSE,
                              glm::value_ptr(s.projection));
    glProgramUniform1f(p, glsl::kHdrMaxLocation, s.hdrMax);
    const bool soft = softFade(s);
    if (soft) {
        glProgramUniform1f(p, glsl::kParticleSoftDistanceLocation, s.softDistance);
        glProgramUniform2f(p, glsl::kParticleNearFarLocation, s.nearPlane, s.farPlane);
        glProgramUniform2f(p, glsl::kParticleDepthTexelsPerPixelLocation, s.depthTexelsPerPixel.x,
                           s.depthTexelsPerPixel.y);
    }
    glUseProgram(p);
    glBindVertexArray(noVertices_.name());
    glBindTextureUnit(glsl::kParticleSpriteBinding, sprite_ ? sprite_.name() : dot_.name());
    glBindTextureUnit(glsl::kParticleSceneDepthBinding, soft ? s.sceneDepth : dot_.name());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, glsl::kParticleEmittersBinding, emitters_.name());
    return true;
}

int ParticleRenderer::drawObjects(const std::vector<GpuParticle>& particles,
                                  const ParticleDrawSettings& s) const {
    if (particles.empty()) return 0;
    const gl::ReloadableProgram& program = this->program(Source::uniforms, s);
    if (!bind(program, s)) return 0;
    const GLuint p = program.name();
    // The chapter's way: every particle is an object with its own uniforms and its own draw call.
    for (const GpuParticle& particle : particles) {
        glProgramUniform4fv(p, glsl::kParticleOneOriginAgeLocation, 1, glm::value_ptr(particle.originAge));
        glProgramUniform4fv(p, glsl::kParticleOneVelocityLifeLocation, 1,
                            glm::value_ptr(particle.velocityLife));
        glProgramUniform4fv(p, glsl::kParticleOneExtraLocation, 1, glm::value_ptr(particle.extra));
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    }
    glBindVertexArray(0);
    return int(particles.size());
}

int ParticleRenderer::drawInstanced(const std::vector<GpuParticle>& particles,
                                    const ParticleDrawSettings& s) {
    if (particles.empty()) return 0;
    if (!bind(program(Source::buffer, s), s)) return 0;
    const std::uint64_t bytes = particles.size() * sizeof(GpuParticle);
    ensureBuffer(instances_, instanceBytes_, bytes, "particles.instances");
    glNamedBufferSubData(instances_.name(), 0, GLsizeiptr(bytes), particles.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, glsl::kParticlePoolBinding, instances_.name());
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(particles.size()));
    glBindVertexArray(0);
    return 1;
}

int ParticleRenderer::drawIndirect(const GpuParticles& pool, const ParticleDrawSettings& s) const {
    // A pool whose programs never built has an instance count of 0: the draw draws nothing.
    if (!bind(program(Source::liveList, s), s)) return 0;
    pool.bindForDraw();
    // The instance count is whatever compact.comp wrote: 0 draws nothing, and is no error.
    glDrawArraysIndirect(GL_TRIANGLE_STRIP, nullptr);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    glBindVertexArray(0);
    return 1;
}

}  // namespace fx
