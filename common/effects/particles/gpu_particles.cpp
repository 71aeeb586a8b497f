#include "effects/particles/gpu_particles.hpp"

#include <algorithm>
#include <vector>

#include "base/log.hpp"
#include "effects/particles/particles_bindings.hpp"
#include "gl/debug_output.hpp"

namespace fx {
namespace {

constexpr GLuint kGroupSize = 256;  // simulate.comp and compact.comp

gl::BufferName buffer(const char* label, GLsizeiptr bytes, GLbitfield flags = GL_DYNAMIC_STORAGE_BIT) {
    gl::BufferName b = gl::createBuffer(label);
    std::vector<unsigned char> zeros(std::size_t(std::max<GLsizeiptr>(bytes, 16)), 0);
    glNamedBufferStorage(b.name(), GLsizeiptr(zeros.size()), zeros.data(), flags);
    return b;
}

}  // namespace

GpuParticles::GpuParticles(const ParticleSystem& system) : capacity_(std::max(system.capacity(), 1u)) {
    pool_ = buffer("particles.pool", GLsizeiptr(capacity_) * GLsizeiptr(sizeof(GpuParticle)));
    live_ = buffer("particles.live", GLsizeiptr(capacity_) * 4);
    // An empty pool draws nothing until the first compaction writes the count.
    const GLuint command[4] = {4, 0, 0, 0};
    command_ = gl::createBuffer("particles.draw_command");
    glNamedBufferStorage(command_.name(), sizeof(command), command, 0);
    stats_ = buffer("particles.stats", 8);
}

std::uint64_t GpuParticles::bytes() const {
    return std::uint64_t(capacity_) * (sizeof(GpuParticle) + 4) + 16 + 8;
}

void GpuParticles::simulate(const ParticleSystem& system, double dt, GLuint emitters) const {
    if (!runnable()) return;
    if (!(dt > 0)) dt = 0;
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, glsl::kParticlePoolBinding, pool_.name());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, glsl::kParticleEmittersBinding, emitters);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, glsl::kParticleLiveBinding, live_.name());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, glsl::kParticleStatsBinding, stats_.name());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, glsl::kParticleCommandBinding, command_.name());

    const GLuint sim = simulate_.name();
    glUseProgram(sim);
    const std::vector<SpawnBatch>& batches = system.lastBatches();
    for (std::size_t e = 0; e < system.emitters().size(); ++e) {
        const GpuEmitter& g = system.emitters()[e];
        const ParticleEmitter& em = system.setups()[e].emitter;
        const SpawnBatch& b = batches[e];
        // One dispatch an emitter, all alike in a debugger's event list but for their group's name.
        gl::DebugGroup group(cat("simulate emitter ", e + 1, " of ", system.emitters().size(),
                                 em.name.empty() ? "" : cat(" (", em.name, ")"), ": ", g.ring.y, " slots"));
        // ring.z is the oldest slot after this frame's spawns; they start `count` slots before it.
        const GLuint head = GLuint((std::uint64_t(g.ring.z) + g.ring.y - b.count % g.ring.y) % g.ring.y);
        glProgramUniform1ui(sim, glsl::kSimulateFirstSlotLocation, g.ring.x);
        glProgramUniform1ui(sim, glsl::kSimulateSlotsLocation, g.ring.y);
        glProgramUniform1ui(sim, glsl::kSimulateHeadLocation, head);
        glProgramUniform1ui(sim, glsl::kSimulateSpawnCountLocation, b.count);
        glProgramUniform1ui(sim, glsl::kSimulateFirstNumberLocation, GLuint(b.firstNumber));
        glProgramUniform1f(sim, glsl::kSimulateNewestAgeLocation, b.newestAge);
        glProgramUniform1f(sim, glsl::kSimulatePeriodLocation, b.period);
        glProgramUniform1f(sim, glsl::kSimulateDtLocation, float(dt));
        glProgramUniform1i(sim, glsl::kSimulateChapterLifetimeLocation,
                           system.setups()[e].rules.chapterLifetime ? 1 : 0);
        glProgramUniform3f(sim, glsl::kSimulateOriginLocation, em.position.x, em.position.y, em.position.z);
        glProgramUniform1f(sim, glsl::kSimulateRiseSpeedLocation, em.riseSpeed);
        glProgramUniform1f(sim, glsl::kSimulateSpreadLocation, em.spread);
        glProgramUniform1ui(sim, glsl::kSimulateSeedLocation, GLuint(em.seed));
        glProgramUniform1f(sim, glsl::kSimulateLifetimeLocation, em.lifetimeSeconds);
        glProgramUniform1ui(sim, glsl::kSimulateEmitterIndexLocation, GLuint(e));
        glDispatchCompute((g.ring.y + kGroupSize - 1) / kGroupSize, 1, 1);
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    const GLuint compact = compact_.name();
    glUseProgram(compact);
    glProgramUniform1ui(compact, glsl::kCompactTotalSlotsLocation, capacity_);
    {
        gl::DebugGroup group("compact the live particles into the indirect draw");
        glDispatchCompute(1, 1, 1);
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    glUseProgram(0);
}

void GpuParticles::drawPoolView(GLuint view, int emitters) const {
    if (!poolView_.usable() || view == 0) return;
    const GLuint p = poolView_.name();
    glProgramUniform1ui(p, glsl::kPoolViewSlotsLocation, capacity_);
    glProgramUniform1f(p, glsl::kPoolViewEmitterScaleLocation,
                       emitters > 1 ? 1.0f / float(emitters - 1) : 0.0f);
    glUseProgram(p);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, glsl::kParticlePoolBinding, pool_.name());
    glBindImageTexture(glsl::kPoolViewImageBinding, view, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute((capacity_ + kGroupSize - 1) / kGroupSize, 1, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glBindImageTexture(glsl::kPoolViewImageBinding, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glUseProgram(0);
}

void GpuParticles::clear() const {
    gl::DebugGroup group("particles: clear the GPU pool");  // a reset happens between frames
    const GLuint zero = 0;
    glClearNamedBufferData(pool_.name(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glClearNamedBufferData(stats_.name(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

void GpuParticles::bindForDraw() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, glsl::kParticlePoolBinding, pool_.name());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, glsl::kParticleLiveBinding, live_.name());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, command_.name());
}

GpuParticleStats GpuParticles::readStats() const {
    GpuParticleStats s;
    GLuint words[2] = {0, 0};
    glGetNamedBufferSubData(stats_.name(), 0, sizeof(words), words);
    s.replaced = words[0];
    s.live = words[1];
    return s;
}

std::vector<GpuParticle> GpuParticles::readPool() const {
    std::vector<GpuParticle> slots(capacity_);
    glGetNamedBufferSubData(pool_.name(), 0, GLsizeiptr(slots.size() * sizeof(GpuParticle)), slots.data());
    return slots;
}

std::array<std::uint32_t, 4> GpuParticles::readDrawCommand() const {
    std::array<std::uint32_t, 4> words{};
    glGetNamedBufferSubData(command_.name(), 0, sizeof(words), words.data());
    return words;
}

std::vector<std::uint32_t> GpuParticles::readLiveList() const {
    std::vector<std::uint32_t> list(readStats().live);
    if (!list.empty()) glGetNamedBufferSubData(live_.name(), 0, GLsizeiptr(list.size() * 4), list.data());
    return list;
}

}  // namespace fx
