#include "fire_lesson.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <imgui.h>

#include "base/log.hpp"
#include "effects/bloom/bloom_settings.hpp"
#include "effects/scene/camera_matrices.hpp"
#include "scene/scene_enums.hpp"

namespace lesson07 {

using namespace fx;

namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

const char* kPathNames[] = {"objects", "instanced", "gpu"};
const int kOffscreenDivisors[] = {1, 2, 4};
// The bench's workloads: every path at every count, in one sweep so their times share one run.
const int kWorkloadCounts[] = {100, 1000, 10000, 100000};

std::vector<std::string> workloadNames() {
    std::vector<std::string> names{"params"};
    for (const char* path : kPathNames)
        for (int count : kWorkloadCounts) names.push_back(cat(path, " ", count));
    return names;
}
constexpr int kInstancedCount = 2000;  // step 3's fire
constexpr int kGpuCount = 100000;      // step 4's fire
// The chapter's emitter moved aside by this much for step 2's two fires (m, along x).
constexpr float kSideBySide = 0.9f;

// A fire of `count` particles alive: the rate follows, and the particles shrink so that together
// they cover about what ten of the chapter's do (small particles: the cost is the count, not fill).
EmitterSetup swarm(EmitterSetup s, int count) {
    ParticleEmitter& e = s.emitter;
    const float chapterAlive = std::max(e.ratePerSecond * e.lifetimeSeconds, 1.0f);
    e.ratePerSecond = float(count) / e.lifetimeSeconds;
    s.sizeScale = std::min(1.0f, std::sqrt(10.0f * chapterAlive / float(count)));
    e.spread = std::max(e.spread, 0.3f * std::abs(e.riseSpeed));
    return s;
}

float emitterRadius(const ParticleEmitter& e) {
    return 0.5f * std::abs(e.riseSpeed) * e.lifetimeSeconds * 1.5f + e.spread * e.lifetimeSeconds +
           std::max(e.startSize, e.endSize);
}

}  // namespace

LessonInfo FireLesson::info() const {
    return {7, "fire-emitter", "Fire emitter", "scenes/07_fire_emitter.json"};
}

std::vector<std::string> FireLesson::steps() const {
    return {
        "The chapter's fire: one object and one draw per particle",
        "What the chapter's fire does wrong after a long frame",
        "One instanced draw for all particles",
        "The simulation on the GPU: compute and an indirect draw",
        "Beyond the chapter: premultiplied, soft, off-screen, smoke and sparks",
    };
}

void FireLesson::declareParams(ParamSet& params) {
    params.addChoice("path", &path_, {"step", "objects", "instanced", "gpu"},
                     "The simulation path: the step's own, one object per particle, one instanced draw, or "
                     "the GPU (compute and an indirect draw)");
    params.addInt(
        "count", &count_, 0, 100000,
        "Particles alive in the fire (0: the step's own: the scene's rate in steps 1 and 2, 2000 in "
        "step 3, 100000 in step 4)");
    // Not a quality knob but the bench's sweep of the three paths at 100 to 100000 particles: one knob,
    // so every row is timed in the same run against the same full-screen copy.
    Param& workload = params.addChoice("workload", &workload_, workloadNames(),
                                       "The bench: a simulation path and a particle count together "
                                       "(params: the path and count parameters)");
    workload.knob = Knob{{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}, 0, "path and particle count"};
    params.addFloat("spin", &spin_, -720.0f, 720.0f,
                    "Degrees per second the fire's sprites turn (the chapter's exercise: 120)");
    params.addFloat("hitch", &hitch_, 0.0f, 2.0f, "Step 2: the long frame added every 120th frame (s)");
    params.addBool("sort", &sort_, "Steps 2 and 3: draw back to front (the fix for the spawn order)");
    Param& soft =
        params.addFloat("soft_distance", &soft_, 0.01f, 4.0f,
                        "Step 5: the particles fade out over this distance in front of the scene (m)");
    soft.knob = Knob{{0.05, 0.1, 0.3, 1.0}, 0.3, "soft-fade distance (m)"};
    Param& offscreen = params.addChoice("offscreen", &offscreen_, {"full", "half", "quarter"},
                                        "Step 5: the resolution of the off-screen particle target");
    offscreen.knob = Knob{{0, 1, 2}, 0, "off-screen resolution"};
    params.addInt("pool", &pool_, 0, 200000, "Slots per emitter (0: from rate x lifetime, with a margin)");
    params.addFloat("threshold", &threshold_, 0.0f, 16.0f, "Bloom: brightness above which light blooms")
        .fromScene("postEffects.bloom.threshold");
    params.addFloat("intensity", &intensity_, 0.0f, 4.0f, "Bloom: the Shader effects chapter's intensity")
        .fromScene("postEffects.bloom.intensity");
}

Status FireLesson::init(const Scene& scene) {
    scene_ = &scene;
    meshes_ = SceneMeshes(scene);
    scenePass_ = HdrScenePass::create();
    chain_ = BloomChain::create();
    bloom_ = BloomComposite::create();
    present_ = OutputTransformPass::create();
    composite_ = FullscreenPass("effects/particles/particles_composite.frag", "particles: composite");
    renderer_ = ParticleRenderer::create();
    // One sprite for every emitter that has one (one texture, one draw); a sprite that cannot be read
    // stops the run with its path.
    const ParticleEmitter* first = nullptr;
    for (const ParticleEmitter& e : scene.emitters) {
        if (e.sprite.empty()) continue;
        if (!first) {
            first = &e;
            if (Status s = renderer_.loadSprite(e.sprite.resolved); !s) return s;
        } else if (e.sprite.resolved != first->sprite.resolved) {
            log::warning("emitter '", e.name, "' asks for sprite ", e.sprite.path,
                         "; lesson 07 draws every emitter with ", first->sprite.path);
        }
    }
    return Status::success();
}

FireLesson::Setup FireLesson::setupFor(int step) const {
    Setup setup;
    const bool beyond = step == Beyond;
    for (const ParticleEmitter& e : scene_->emitters) {
        if (!beyond && e.kind != EmitterKind::fire) continue;  // smoke and sparks are step 5's
        EmitterSetup s{e, {}, pool_, 1.0f, !e.sprite.empty() && renderer_.hasSprite()};
        if (e.kind == EmitterKind::fire) s.emitter.spinDegreesPerSecond += spin_;
        if (step == Objects) s.rules = {true, true};
        if (step == Hitch) {
            // Two fires side by side: the chapter's rules on the left, the fixed ones on the right.
            EmitterSetup chapter = s;
            chapter.rules = {true, true};
            chapter.emitter.position.x -= kSideBySide;
            setup.emitters.push_back(chapter);
            s.emitter.position.x += kSideBySide;
        }
        int count = count_ > 0 ? count_ : step == Instanced ? kInstancedCount : step == Gpu ? kGpuCount : 0;
        if (workload_ > 0) count = kWorkloadCounts[(workload_ - 1) % 4];
        if (count > 0 && e.kind == EmitterKind::fire) s = swarm(s, count);
        setup.emitters.push_back(s);
    }
    if (step == Hitch) {
        // The chapter's emitters first, so the fixed ones are the tail that gets sorted.
        std::stable_partition(setup.emitters.begin(), setup.emitters.end(),
                              [](const EmitterSetup& s) { return s.rules.chapterLifetime; });
        setup.sortedFrom = int(std::count_if(setup.emitters.begin(), setup.emitters.end(),
                                             [](const EmitterSetup& s) { return s.rules.chapterLifetime; }));
    }
    setup.path = step == Objects || step == Hitch ? Path::objects
                 : step == Instanced              ? Path::instanced
                                                  : Path::gpu;
    if (path_ > 0) setup.path = static_cast<Path>(path_ - 1);
    if (workload_ > 0) setup.path = static_cast<Path>(std::clamp((workload_ - 1) / 4, 0, 2));
    setup.sort = (step == Hitch || step == Instanced) && sort_ && setup.path != Path::gpu;
    setup.premultiplied = beyond;
    return setup;
}

bool FireLesson::hitchOn(const FrameInfo& frame) const {
    return frame.step == Hitch && hitch_ > 0.0f && frame.index % 120 == 2;
}

void FireLesson::configure(const Setup& setup) {
    setup_ = setup;
    configured_ = true;
    const bool gpu = setup.path == Path::gpu;
    system_ = ParticleSystem(setup.emitters, !gpu);
    gpu_ = gpu ? GpuParticles::create(system_) : GpuParticles();
    restart();
}

void FireLesson::restart() {
    const bool gpu = setup_.path == Path::gpu;
    system_ = ParticleSystem(setup_.emitters, !gpu);
    gpu_.clear();
    // Start from a steady flame. The fixed rules catch up in one step (every spawn owed, born at its
    // time); the chapter's timer needs frame by frame.
    double longest = 0;
    bool chapter = false;
    for (const EmitterSetup& s : setup_.emitters) {
        longest = std::max(longest, double(s.emitter.lifetimeSeconds));
        chapter = chapter || s.rules.chapterTimer;
    }
    firstDt_ = 0;
    if (chapter)
        system_.prewarm(longest);
    else if (gpu)
        firstDt_ = longest;
    else
        system_.update(longest);
}

void FireLesson::simulate(double dt) {
    Clock::time_point start = Clock::now();
    dt += std::exchange(firstDt_, 0.0);
    system_.update(dt);
    renderer_.setEmitters(system_.emitters());
    if (setup_.path == Path::gpu) {
        gpu_.simulate(system_, dt, renderer_.emitterBuffer());
        visible_.clear();
    } else {
        system_.collect(visible_);
        CameraMatrices camera = cameraMatrices(scene_->camera, 1, 1);
        auto sortedBegin = std::find_if(visible_.begin(), visible_.end(), [this](const GpuParticle& p) {
            return int(p.extra.y) >= setup_.sortedFrom;
        });
        if (setup_.sort) {
            std::vector<GpuParticle> tail(sortedBegin, visible_.end());
            ParticleSystem::sortBackToFront(tail, camera.view);
            std::copy(tail.begin(), tail.end(), sortedBegin);
        }
        // What the panel counts: alpha below 0 drawn (the chapter's rule), and pairs drawn front first.
        negativeAlpha_ = 0;
        outOfOrder_ = 0;
        for (std::size_t i = 0; i < visible_.size(); ++i) {
            const GpuParticle& p = visible_[i];
            const GpuEmitter& e = system_.emitters()[std::size_t(p.extra.y)];
            float t = p.originAge.w / std::max(p.velocityLife.w, 1e-6f);
            if (e.motion.y > 0.0f && e.startColor.a + (e.endColor.a - e.startColor.a) * t < 0.0f)
                ++negativeAlpha_;
            if (i > 0 && visible_[i - 1].extra.y == p.extra.y) {
                auto depth = [&](const GpuParticle& q) {
                    glm::vec3 at = glm::vec3(q.originAge) + glm::vec3(q.velocityLife) * q.originAge.w;
                    return (camera.view * glm::vec4(at, 1.0f)).z;
                };
                if (depth(p) < depth(visible_[i - 1])) ++outOfOrder_;  // p is farther, drawn later
            }
        }
    }
    simulateMs_ = msSince(start);
}

void FireLesson::drawPoolView(GLuint texture, int rows) const {
    if (setup_.path == Path::gpu) {
        gpu_.drawPoolView(texture, int(system_.emitters().size()));
    } else {
        std::vector<float> texels = system_.poolViewTexels(rows);
        glTextureSubImage2D(texture, 0, 0, 0, 256, rows, GL_RGBA, GL_FLOAT, texels.data());
    }
}

int FireLesson::draw(const ParticleDrawSettings& settings) {
    Clock::time_point start = Clock::now();
    int calls = 0;
    switch (setup_.path) {
        case Path::objects:
            calls = renderer_.drawObjects(visible_, settings);
            break;
        case Path::instanced:
            calls = renderer_.drawInstanced(visible_, settings);
            break;
        case Path::gpu:
            calls = renderer_.drawIndirect(gpu_, settings);
            break;
    }
    drawCpuMs_ = msSince(start);
    drawCalls_ = calls;
    return calls;
}

bool FireLesson::anyEmitterInView(const FrameInfo& frame) const {
    CameraMatrices camera = cameraMatrices(scene_->camera, frame.size.width, frame.size.height);
    const glm::mat4 m = glm::transpose(camera.viewProjection);
    // The six planes of the view volume (Gribb and Hartmann), each as (normal, distance).
    const glm::vec4 planes[6] = {m[3] + m[0], m[3] - m[0], m[3] + m[1],
                                 m[3] - m[1], m[3] + m[2], m[3] - m[2]};
    for (const EmitterSetup& s : setup_.emitters) {
        const ParticleEmitter& e = s.emitter;
        glm::vec3 centre = e.position + glm::vec3(0.0f, 0.5f * e.riseSpeed * e.lifetimeSeconds, 0.0f);
        float radius = emitterRadius(e) * std::max(s.sizeScale, 1.0f);
        bool inside = true;
        for (const glm::vec4& plane : planes) {
            float length = std::max(glm::length(glm::vec3(plane)), 1e-12f);
            if ((glm::dot(glm::vec3(plane), centre) + plane.w) / length < -radius) inside = false;
        }
        if (inside) return true;
    }
    return false;
}

void FireLesson::buildFrame(FrameGraph& graph, const FrameInfo& frame) {
    const int step = frame.step;
    HdrSceneTargets hdr = scenePass_.declare(graph, *scene_, meshes_, frame.seconds);
    const bool particles = !lacks(graph, SceneFeature::particles);

    // The simulation's setup follows the step and the parameters; a change starts it over. Without an
    // emitter in the scene nothing is made: no buffer, no dispatch.
    const Setup wanted = setupFor(step);
    if (particles && (!configured_ || !(wanted == setup_))) {
        configure(wanted);
    } else if (particles && frame.benchmark) {
        restart();  // every bench frame of a setting draws the same picture, at a steady frame's cost
    }
    hitchNow_ = hitchOn(frame);
    pendingDt_ = frame.deltaSeconds + (hitchNow_ ? double(hitch_) : 0.0);

    const std::string notInView = "every emitter's bounds are outside the view";
    const bool inView = particles && anyEmitterInView(frame);
    const Camera& cam = scene_->camera;
    {
        PassGroup::Scope in(graph, particleGroup_);
        Pass& sim = graph.addPass("particles.simulate", [this](PassContext&) { simulate(pendingDt_); });
        sim.keepAlive();

        // The pool in the inspector (particles.pool): one texel per slot. Nothing reads it, so the
        // graph runs this pass only when someone inspects or captures it.
        const int rows = std::max(1, int((system_.capacity() + 255) / 256));
        Pass& poolView = graph.addPass("particles.pool view", [this, rows](PassContext& ctx) {
            drawPoolView(GLuint(ctx.native(poolTexture_)), rows);
        });
        poolTexture_ =
            poolView.create("particles.pool", {TextureSize::absolute(256, rows), TextureFormat::RGBA32F, 1},
                            TextureUsage::Storage);

        if (!wanted.premultiplied) {
            // Steps 1 to 4: straight into scene.color, tested against scene.depth with depth writes off
            // (the chapter's transparent queue), straight alpha.
            Pass& drawPass = graph.addPass("particles.draw", [this, cam](PassContext& ctx) {
                Size2D size = ctx.targetSize();
                CameraMatrices camera = cameraMatrices(cam, size.width, size.height);
                ParticleDrawSettings s;
                s.view = camera.view;
                s.projection = camera.projection;
                s.hdrMax = kSceneHdrMax;
                draw(s);
            });
            drawPass.modify(hdr.color, TextureUsage::ColorAttachment)
                .modify(hdr.depth, TextureUsage::DepthAttachment)
                .setState({.depthTest = true,
                           .depthWrite = false,
                           .depthFunction = DepthFunction::Less,
                           .blend = true,
                           .blendFunction = BlendFunction::alpha(),
                           .faceCulling = false,
                           .colorMask = ColorMask{}});
            if (particles && !inView) drawPass.notCalledFor(notInView);
        } else {
            // Step 5: premultiplied particles into their own target (a fraction of the output), faded
            // by scene.depth read as a texture (no depth attachment: no feedback loop), then laid over
            // scene.color. The target is 32-bit float: additive light sums without limit there, and the
            // composite clamps it before the 16-bit scene.color.
            const int divisor = kOffscreenDivisors[std::clamp(offscreen_, 0, 2)];
            const float soft = std::max(soft_, 0.01f);  // 0 would divide by 0: refused
            const TextureHandle depth = hdr.depth;
            Pass& off = graph.addPass("particles.offscreen", [this, cam, depth, soft](PassContext& ctx) {
                Size2D size = ctx.targetSize();
                const auto& d = ctx.texture(depth);
                CameraMatrices camera = cameraMatrices(cam, size.width, size.height);
                ParticleDrawSettings s;
                s.view = camera.view;
                s.projection = camera.projection;
                s.premultiplied = true;
                s.hdrMax = kSceneHdrMax;
                s.softDistance = soft;
                s.sceneDepth = GLuint(d.native);
                s.nearPlane = cam.near;
                s.farPlane = cam.far;
                s.depthTexelsPerPixel = {float(d.spec.width) / float(std::max(size.width, 1)),
                                         float(d.spec.height) / float(std::max(size.height, 1))};
                draw(s);
            });
            TextureHandle color = off.create(
                "particles.color", {TextureSize::outputFraction(1, divisor), TextureFormat::RGBA32F, 1},
                TextureUsage::ColorAttachment);
            off.read(hdr.depth).setState({.depthTest = false,
                                          .depthWrite = false,
                                          .blend = true,
                                          .blendFunction = BlendFunction::premultipliedAlpha(),
                                          .faceCulling = false,
                                          .colorMask = ColorMask{},
                                          .clearColor = ClearColor{0, 0, 0, 0}});
            if (particles && !inView) off.notCalledFor(notInView);
            const FullscreenPass* composite = &composite_;
            Pass& over = graph.addPass("particles.composite", [composite, color](PassContext& ctx) {
                glProgramUniform1f(composite->program(), 0, kSceneHdrMax);
                composite->draw({GLuint(ctx.native(color))});
            });
            PassState state = FullscreenPass::state();
            state.blend = true;
            state.blendFunction = BlendFunction::premultipliedAlpha();
            over.read(color).modify(hdr.color, TextureUsage::ColorAttachment).setState(state);
        }
    }

    // Lesson 06's bloom, the Shader effects chapter's chain, downstream of the particles.
    TextureHandle shown = hdr.color;
    {
        PassGroup::Scope in(graph, bloomGroup_);
        BloomChainSettings settings = chapter000Bloom(threshold_, intensity_, 6);
        BloomChain::Declared d = chain_.declare(graph, hdr.color, settings);
        if (!d.empty()) {
            BloomCompositeSettings c{settings.filters, settings.upOffset,
                                     chapter000CompositeScale(int(d.levels.size()))};
            DeclaredPass result = bloom_.declare(graph, hdr.color, d.glow(), c);
            if (!lacks(graph, SceneFeature::bloom)) shown = result.output;
        }
    }
    // Steps 1 and 2 clip like the chapter; from step 3 a filmic curve keeps the flame's colour.
    present_.declare(graph, shown, std::nullopt, step <= Hitch ? ToneCurve::clip : ToneCurve::filmic, 1.0f);
}

void FireLesson::drawPanel(const FrameInfo& frame) {
    switch (frame.step) {
        case Objects:
            ImGui::TextWrapped("Every particle is one draw call with its own uniforms.");
            break;
        case Hitch:
            ImGui::TextWrapped(
                "Left: the chapter's rules. Right: the fixes. Every 120th frame is %.2f s long; watch the "
                "left flame flash dark and then spawn a burst.",
                double(hitch_));
            break;
        case Instanced:
            ImGui::TextWrapped("One draw call; the CPU still moves every particle.");
            break;
        case Gpu:
            ImGui::TextWrapped("Compute shaders simulate; the CPU only counts spawns.");
            break;
        default:
            ImGui::TextWrapped("Inspect particles.color: the off-screen target.");
            break;
    }
}

void FireLesson::facts(Facts& out, const FrameInfo& frame) const {
    if (!scene_ || scene_->emitters.empty()) {
        out.add("particles", "none", "the scene has no emitter: no buffer, no dispatch, no particle pass");
        out.add("poolBytes", "0", "particle pool (bytes)");
        return;
    }
    if (!configured_) return;
    out.add("path", kPathNames[int(setup_.path)], "simulation path");
    out.add("drawCalls", std::to_string(drawCalls_), "particle draw calls");
    std::uint32_t live = system_.liveCount();
    std::uint64_t replaced = system_.replacedCount();
    if (setup_.path == Path::gpu && !frame.benchmark) {
        GpuParticleStats stats = gpu_.readStats();
        live = stats.live;
        replaced = stats.replaced;
    }
    out.add("live", std::to_string(live), "particles alive");
    out.add("capacity", std::to_string(system_.capacity()), "pool slots");
    out.add("replaced", std::to_string(replaced), "pool full: oldest particles replaced");
    out.add("dropped", std::to_string(system_.droppedCount()), "pool full: new particles dropped");
    out.add("simulateCpuMs", cat(simulateMs_), "simulation on the CPU (ms)");
    out.add("drawCpuMs", cat(drawCpuMs_), "issuing the draws on the CPU (ms)");
    out.add("spawnedLastFrame", std::to_string(system_.spawnedLastFrame()), "spawned this frame");
    std::uint64_t bytes = setup_.path == Path::gpu ? gpu_.bytes() : renderer_.instanceBytes();
    out.add("poolBytes", std::to_string(bytes), "particle buffers (bytes)");
    out.add("buffers",
            setup_.path == Path::gpu
                ? "particles.pool, particles.live, particles.draw_command, particles.stats, "
                  "particles.emitters"
            : setup_.path == Path::instanced ? "particles.instances, particles.emitters"
                                             : "particles.emitters (and one set of uniforms per particle)",
            "particle buffers (GL labels)");
    if (frame.step == Hitch) {
        out.add("hitch", hitchNow_, "this frame was long");
        out.add("negativeAlpha", std::to_string(negativeAlpha_), "particles drawn with alpha below 0 (left)");
        std::uint32_t chapterBacklog = 0;
        for (std::size_t e = 0; e < system_.clocks().size(); ++e) {
            if (system_.setups()[e].rules.chapterTimer)
                chapterBacklog +=
                    std::uint32_t(system_.clocks()[e].backlog() * system_.setups()[e].emitter.ratePerSecond);
        }
        out.add("chapterBacklog", std::to_string(chapterBacklog),
                "spawns the chapter's timer still owes (left)");
    }
    if (frame.step <= Instanced)
        out.add("outOfOrder", std::to_string(outOfOrder_), "pairs drawn front before back");
    if (frame.previousFrame) {
        out.add("particlesMs", cat(particleGroup_.timeMs(*frame.previousFrame)), "particle passes (ms)");
        out.add("frameMs", cat(frame.previousFrame->timedMs()), "all passes (ms)");
    }
}

}  // namespace lesson07
