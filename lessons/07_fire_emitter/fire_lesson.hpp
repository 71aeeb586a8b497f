#pragma once
// Lesson 07's class, shared by its steps and frame (fire_lesson.cpp) and its simulation paths
// (fire_simulation.cpp).
//
// Lesson 07: the fire emitter (Shader effects §3.8, hard cases 22 to 25; docs/chapters.md). The
// chapter's fire (one object and one draw per particle, simulated on the CPU), what it does wrong
// after a long frame, one instanced draw, the simulation on the GPU with an indirect draw, then what
// the chapter leaves out: premultiplied alpha, soft particles, off-screen particles, smoke and sparks.
// Lesson 06's bloom makes the fire glow.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/lesson.hpp"
#include "effects/bloom/bloom_chain.hpp"
#include "effects/bloom/bloom_composite.hpp"
#include "effects/particles/gpu_particles.hpp"
#include "effects/particles/particle_budget.hpp"
#include "effects/particles/particle_renderer.hpp"
#include "effects/particles/particle_system.hpp"
#include "effects/post/fullscreen_pass.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "effects/scene/scene_meshes.hpp"

namespace lesson07 {

inline constexpr const char* kPathNames[] = {"objects", "instanced", "gpu"};
// The bench's workloads: every path at every count, in one sweep so their times share one run.
inline constexpr int kWorkloadCounts[] = {100, 1000, 10000, 100000};
inline constexpr int kInstancedCount = 2000;  // step 3's fire
inline constexpr int kGpuCount = 100000;      // step 4's fire
// The chapter's emitter moved aside by this much for step 2's two fires (m, along x).
inline constexpr float kSideBySide = 0.9f;

class FireLesson final : public fx::Lesson {
public:
    std::vector<std::string> steps() const override;
    void declareParams(fx::ParamSet& params) override;
    fx::Status init(const fx::Scene& scene) override;
    void update(const fx::FrameInfo& frame) override;
    void buildFrame(fx::FrameGraph& graph, const fx::FrameInfo& frame) override;
    void drawPanel(const fx::FrameInfo& frame) override;
    void facts(fx::Facts& out, const fx::FrameInfo& frame) const override;
    int benchStep() const override { return Beyond; }
    std::string benchTexture() const override { return "scene.color"; }

    enum Step { Objects, Hitch, Instanced, Gpu, Beyond };
    enum class Path { objects, instanced, gpu };  // named by kPathNames, in this order
    static constexpr Path kPaths[] = {Path::objects, Path::instanced, Path::gpu};
    enum class Offscreen { full, half, quarter };  // step 5's particle target against the output

    // What a step simulates and how: the emitters (with their rules), the path and the blend.
    struct Setup {
        std::vector<fx::EmitterSetup> emitters;
        Path path = Path::objects;
        bool sort = false;              // back to front before drawing (the CPU paths)
        int sortedFrom = 0;             // sort only the particles of emitters from this index on
        bool premultiplied = false;     // step 5: one blend for fire and smoke
        std::size_t sceneEmitters = 0;  // the scene's emitters behind `emitters` (step 2 doubles them)
        bool operator==(const Setup&) const = default;
    };
    Setup setupFor(const fx::FrameInfo& frame) const;
    // The 0.5 s long frame of step 2 lands on this frame (the lesson clock's third step, then every 120th).
    bool hitchOn(const fx::FrameInfo& frame) const;

private:
    void configure(const Setup& setup);
    void restart();  // the steady flame again, from the same state (prewarmed)
    void simulate(double dt, const fx::Camera& sceneCamera);  // the "particles.simulate" pass body
    int draw(const fx::ParticleDrawSettings& settings);       // the draw pass bodies: draw calls made
    bool anyEmitterInView(const fx::FrameInfo& frame) const;
    bool holdingAlpha(const fx::FrameInfo& frame) const { return frame.step == Objects && holdAlpha_ > 0.0f; }
    void drawPoolView(GLuint texture, int rows) const;  // the "particles.pool view" pass body

    // Parameters.
    // The bench's workload: a path and a particle count together (no path: the parameters decide).
    struct Workload {
        std::optional<Path> path;
        int count = 0;
    };
    static std::vector<fx::TableChoice<std::optional<Path>>::Option> pathTable();
    static std::vector<fx::TableChoice<Workload>::Option> workloadTable();
    fx::TableChoice<std::optional<Path>> path_{pathTable(), "step"};  // none: the step's own path
    int count_ = 0;       // particles alive in the fire (0: the step's own)
    float spin_ = 0.0f;   // deg/s added to the fire (the chapter's exercise: 120)
    float hitch_ = 0.5f;  // step 2: the long frame (s)
    bool sort_ = true;    // steps 2 (fixed side) and 3: back to front
    float soft_ = 0.3f;   // step 5: soft-fade distance (m)
    fx::Choice<Offscreen> offscreen_{Offscreen::half};  // step 5: the particles' target's resolution
    int pool_ = 0;                                      // slots per emitter (0: from rate x lifetime)
    fx::TableChoice<Workload> workload_{workloadTable(), "params"};  // the bench's sweep
    float threshold_, intensity_;  // the chapter's bloom (lesson 06, step 3): the scene's settings
    bool flipSprite_ = false;      // the raw-GL mistake: the sprite's file rows uploaded top first
    float holdAlpha_ = 0.0f;       // step 1: one particle with this alpha (0: the chapter's fire)
    fx::ParticleRenderer::SpriteRows spriteRows_ = fx::ParticleRenderer::SpriteRows::bottomFirst;
    std::filesystem::path spritePath_;  // the sprite loaded, loaded again when flip_sprite changes

    fx::Gpu<fx::HdrScenePass> scenePass_;
    fx::Gpu<fx::ParticleRenderer> renderer_;
    fx::Gpu<fx::FullscreenPass> composite_{"effects/particles/particles_composite.frag",
                                           "particles: composite"};
    fx::Gpu<fx::BloomChain> chain_;
    fx::Gpu<fx::BloomComposite> bloom_;
    fx::Gpu<fx::OutputTransformPass> present_;
    fx::PassGroup particleGroup_ = fx::groupNeeding(fx::SceneFeature::particles);
    fx::PassGroup bloomGroup_ = fx::groupNeeding(fx::SceneFeature::bloom);

    // The simulation, rebuilt when the step's setup changes.
    Setup setup_;
    bool configured_ = false;
    fx::gl::DeviceLimits device_;
    std::vector<fx::EmitterSetup> fitted_;  // setup_'s emitters fitted to the particle budget
    fx::ParticleBudget budget_;
    fx::ParticleSystem system_;
    std::optional<fx::GpuParticles> gpu_;   // the GPU path's pool, made when that path is configured
    double firstDt_ = 0;                    // the GPU's first frame also runs the prewarm
    std::vector<fx::GpuParticle> visible_;  // CPU paths: the live particles in draw order
    double pendingDt_ = 0;                  // time since the simulation last ran, for the pass body
    bool hitchNow_ = false;
    fx::TextureHandle poolTexture_;  // this frame's particles.pool (the pool view pass writes it)
    double simulateMs_ = 0, drawCpuMs_ = 0;
    int drawCalls_ = 0;
    int negativeAlpha_ = 0;  // step 2: particles drawn with alpha below 0 (the chapter's side)
    int outOfOrder_ = 0;     // pairs drawn front before back (transparent order)
    fx::GpuParticleStats gpuStats_;
};

}  // namespace lesson07
