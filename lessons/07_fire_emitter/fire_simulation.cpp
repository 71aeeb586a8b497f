// Lesson 07's three simulation paths: what each step sets up, the CPU simulation and its clock, the
// draw, and whether any emitter can be seen. The steps and the frame are in fire_lesson.cpp.
#include <algorithm>
#include <chrono>
#include <cmath>

#include "base/log.hpp"
#include "effects/scene/camera_matrices.hpp"
#include "fire_lesson.hpp"

namespace lesson07 {

using namespace fx;

namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

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

// hold_alpha: one particle as the chapter's is at half its life (1 m up, 1.25 m wide), standing still
// with its alpha held. One slot: each spawn replaces the particle with its twin, so the picture holds.
EmitterSetup heldParticle(EmitterSetup s, float alpha) {
    ParticleEmitter& e = s.emitter;
    e.position.y += 0.5f * e.riseSpeed * e.lifetimeSeconds;
    e.startSize = e.endSize = 0.5f * (e.startSize + e.endSize);
    e.riseSpeed = 0.0f;
    e.spread = 0.0f;
    e.startColor.a = e.endColor.a = alpha;
    s.capacity = 1;
    s.sizeScale = 1.0f;
    return s;
}

float emitterRadius(const ParticleEmitter& e) {
    return 0.5f * std::abs(e.riseSpeed) * e.lifetimeSeconds * 1.5f + e.spread * e.lifetimeSeconds +
           std::max(e.startSize, e.endSize);
}

}  // namespace

FireLesson::Setup FireLesson::setupFor(const FrameInfo& frame) const {
    const int step = frame.step;
    Setup setup;
    const bool beyond = step == Beyond;
    for (const ParticleEmitter& e : frame.world.scene().emitters) {
        if (!beyond && e.kind != EmitterKind::fire) continue;  // smoke and sparks are step 5's
        ++setup.sceneEmitters;
        EmitterSetup s{e, {}, pool_, 1.0f, !e.sprite.empty() && renderer_->hasSprite()};
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
        if (workload_->path) count = workload_->count;
        if (count > 0 && e.kind == EmitterKind::fire) s = swarm(s, count);
        if (holdingAlpha(frame) && e.kind == EmitterKind::fire) s = heldParticle(s, holdAlpha_);
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
    if (*path_) setup.path = **path_;
    if (workload_->path) setup.path = *workload_->path;
    setup.sort = (step == Hitch || step == Instanced) && sort_ && setup.path != Path::gpu;
    setup.premultiplied = beyond;
    return setup;
}

bool FireLesson::hitchOn(const FrameInfo& frame) const {
    // Counted on the lesson clock: a paused clock adds no hitch, and a window at any frame rate has its
    // hitches on the same frames as a headless run (the third step, then every 120th).
    return frame.step == Hitch && hitch_ > 0.0f && frame.deltaSeconds > 0 && frame.clockSteps % 120 == 3;
}

void FireLesson::configure(const Setup& setup) {
    setup_ = setup;
    configured_ = true;
    // The scene and the parameters together may ask for more than the device holds: fitted first.
    fitted_ = setup.emitters;
    budget_ = fitParticleBudget(fitted_, device_);
    budget_.sceneEmitters = setup.sceneEmitters;
    if (budget_.clamped()) log::warning("lesson 07: ", budget_.warning());
    const bool gpu = setup.path == Path::gpu;
    system_ = ParticleSystem(fitted_, !gpu);
    if (gpu)
        gpu_.emplace(system_);
    else
        gpu_.reset();
    restart();
}

void FireLesson::restart() {
    const bool gpu = setup_.path == Path::gpu;
    system_ = ParticleSystem(fitted_, !gpu);
    if (gpu_) gpu_->clear();
    // Start from a steady flame. The fixed rules catch up in one step (every spawn owed, born at its
    // time); the chapter's timer needs frame by frame.
    double longest = 0;
    bool chapter = false;
    for (const EmitterSetup& s : setup_.emitters) {
        longest = std::max(longest, double(s.emitter.lifetimeSeconds));
        chapter = chapter || s.rules.chapterTimer;
    }
    firstDt_ = 0;
    pendingDt_ = 0;  // a restarted simulation owes no time from before
    if (chapter)
        system_.prewarm(longest);
    else if (gpu)
        firstDt_ = longest;
    else
        system_.update(longest);
}

void FireLesson::simulate(double dt, const Camera& sceneCamera) {
    Clock::time_point start = Clock::now();
    dt += std::exchange(firstDt_, 0.0);
    system_.update(dt);
    renderer_->setEmitters(system_.emitters());
    if (setup_.path == Path::gpu) {
        gpu_->simulate(system_, dt, renderer_->emitterBuffer());
        visible_.clear();
    } else {
        system_.collect(visible_);
        CameraMatrices camera = cameraMatrices(sceneCamera, 1, 1);
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
        gpu_->drawPoolView(texture, int(system_.emitters().size()));
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
            calls = renderer_->drawObjects(visible_, settings);
            break;
        case Path::instanced:
            calls = renderer_->drawInstanced(visible_, settings);
            break;
        case Path::gpu:
            calls = renderer_->drawIndirect(*gpu_, settings);
            break;
    }
    drawCpuMs_ = msSince(start);
    drawCalls_ = calls;
    return calls;
}

bool FireLesson::anyEmitterInView(const FrameInfo& frame) const {
    CameraMatrices camera = cameraMatrices(frame.world.scene().camera, frame.size.width, frame.size.height);
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

}  // namespace lesson07
