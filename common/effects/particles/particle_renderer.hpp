#pragma once
// Drawing particles as camera-facing sprites (shaders/effects/particles/particle.vert and .frag), three
// ways, the three paths of lesson 07:
//   drawObjects:   one draw and one set of uniforms per particle (the Shader effects chapter: every
//                  particle a game object with a Billboard);
//   drawInstanced: the live particles uploaded to one buffer, one instanced draw;
//   drawIndirect:  the GPU pool's live list and instance count (gpu_particles.hpp), one indirect draw.
// The sprite is the scene's particle texture (only its alpha is used); the emitter table is uploaded
// once a frame to particles.emitters.
//
// Each draw's choices (where the particle comes from, the soft fade on or off, premultiplied or
// straight alpha) are built into its program as #defines, one program per set of choices, each built
// the first time a draw asks for it and labelled with its choices ("particles: sprites (instanced,
// soft, premultiplied)"). Uniforms and branches would be the same picture, but llvmpipe runs both
// sides of a branch even on a uniform, so every vertex would read all three sources and every pixel
// would fetch and linearise the scene's depth with the fade off (docs/bench.md, Lesson 07).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "base/result.hpp"
#include "effects/particles/gpu_particles.hpp"
#include "effects/particles/particle_layout.hpp"
#include "gl/object.hpp"
#include "gl/program.hpp"
#include "gl/texture.hpp"

namespace fx {

struct ParticleDrawSettings {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    bool premultiplied = false;  // false: the chapter's straight alpha
    float hdrMax = 4096.0f;      // emission clamp (kSceneHdrMax)
    // Soft particles: <= 0 off. On, the fragment reads `sceneDepth` (never attached to the target).
    float softDistance = 0.0f;
    GLuint sceneDepth = 0;
    float nearPlane = 0.1f, farPlane = 100.0f;
    glm::vec2 depthTexelsPerPixel{1.0f};
};

class ParticleRenderer {
public:
    // Builds the chapter's program (one draw per particle, straight alpha, no fade), so a shader that
    // does not build shows at once; the others are built when a draw first needs them. A draw whose
    // program does not build draws nothing (the runner lists the error).
    ParticleRenderer();

    // Which of the picture's rows the texture's first row (v = 0, the quad's bottom) holds.
    enum class SpriteRows {
        bottomFirst,  // the picture's bottom row, as GL counts rows (readPng's order): upright
        topFirst,     // the file's first row, as raw GL code that uploads a decoder's rows: upside down
    };
    // The sprite from a PNG file: an error that names the path when it cannot be read.
    Status loadSprite(const std::filesystem::path& path, SpriteRows rows = SpriteRows::bottomFirst);
    bool hasSprite() const { return static_cast<bool>(sprite_); }

    // Uploads the emitter table (every path reads it at binding 1).
    void setEmitters(const std::vector<GpuEmitter>& emitters);
    GLuint emitterBuffer() const { return emitters_.name(); }

    // Each returns the number of draw calls it made.
    int drawObjects(const std::vector<GpuParticle>& particles, const ParticleDrawSettings& s) const;
    int drawInstanced(const std::vector<GpuParticle>& particles, const ParticleDrawSettings& s);
    int drawIndirect(const GpuParticles& pool, const ParticleDrawSettings& s) const;

    std::uint64_t instanceBytes() const { return instanceBytes_; }

    // Where a draw's particles come from (PARTICLE_SOURCE in particle.vert).
    enum class Source { buffer = 0, liveList = 1, uniforms = 2 };
    // The program for a draw from `source` with `s`'s fade and blend, built the first time it is asked
    // for.
    const gl::ReloadableProgram& program(Source source, const ParticleDrawSettings& s) const;
    // Programs built so far (tests: a draw builds only the one it needs).
    int programsBuilt() const;

private:
    // Sets the uniforms `program` has, binds it, the sprite, the depth and the emitters; false when
    // the program does not build (nothing to draw with).
    bool bind(const gl::ReloadableProgram& program, const ParticleDrawSettings& s) const;

    // [source * 4 + soft * 2 + premultiplied]
    mutable std::optional<gl::ReloadableProgram> programs_[12];
    gl::VertexArrayName noVertices_;  // core GL draws need a vertex array; the shader makes the corners
    gl::Texture sprite_;
    gl::Texture dot_;  // a 1x1 white texture bound in place of a missing sprite
    gl::BufferName emitters_;
    std::size_t emitterBytes_ = 0;
    gl::BufferName instances_;
    std::uint64_t instanceBytes_ = 0;
};

}  // namespace fx
