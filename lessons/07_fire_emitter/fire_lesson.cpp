#include "fire_lesson.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include <imgui.h>

#include "app/runner.hpp"
#include "base/log.hpp"
#include "effects/bloom/bloom_settings.hpp"
#include "effects/scene/camera_matrices.hpp"
#include "image/view_transform.hpp"
#include "scene/scene_enums.hpp"
#include "scene/scene_settings.hpp"

namespace lesson07 {

using namespace fx;

namespace {

// Step 5's off-screen target: the output's size divided by this.
int divisorOf(FireLesson::Offscreen resolution) {
    switch (resolution) {
        case FireLesson::Offscreen::full:
            return 1;
        case FireLesson::Offscreen::half:
            return 2;
        case FireLesson::Offscreen::quarter:
            return 4;
    }
    return 1;
}

}  // namespace

std::vector<TableChoice<std::optional<FireLesson::Path>>::Option> FireLesson::pathTable() {
    std::vector<TableChoice<std::optional<Path>>::Option> table{{"step", std::nullopt}};
    for (Path path : kPaths) table.push_back({kPathNames[int(path)], path});
    return table;
}

std::vector<TableChoice<FireLesson::Workload>::Option> FireLesson::workloadTable() {
    std::vector<TableChoice<Workload>::Option> table{{"params", {}}};
    for (Path path : kPaths)
        for (int count : kWorkloadCounts)
            table.push_back({cat(kPathNames[int(path)], " ", count), {path, count}});
    return table;
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
    params.addChoice("path", &path_);
    params.addInt("count", &count_, 0, 100000).showZeroAs();
    // Not a quality knob but the bench's sweep of the three paths at 100 to 100000 particles: one knob,
    // so every row is timed in the same run against the same full-screen copy.
    Param& workload = params.addChoice("workload", &workload_);
    workload.knob = Knob{{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}, 0, "path and particle count"};
    params.addFloat("spin", &spin_, -720.0f, 720.0f);
    params.addFloat("hitch", &hitch_, 0.0f, 2.0f).inSteps({Hitch});
    params.addBool("sort", &sort_).inSteps({Hitch, Instanced});
    Param& soft = params.addFloat("soft_distance", &soft_, 0.01f, 4.0f);
    soft.knob = Knob{{0.05, 0.1, 0.3, 1.0}, 0.3, "soft-fade distance (m)"};
    soft.inSteps({Beyond});
    Param& offscreen = params.addChoice("offscreen", &offscreen_, {"full", "half", "quarter"});
    offscreen.knob = Knob{{0, 1, 2}, 0, "off-screen resolution"};
    offscreen.inSteps({Beyond});
    params.addInt("pool", &pool_, 0, 200000).showZeroAs();
    params.addBool("flip_sprite", &flipSprite_);
    params.addFloat("hold_alpha", &holdAlpha_, 0.0f, 1.0f).showZeroAs().inSteps({Objects});
    params.addSetting("threshold", &threshold_, sceneSetting("postEffects.bloom.threshold"));
    params.addSetting("intensity", &intensity_, sceneSetting("postEffects.bloom.intensity"));
}

Status FireLesson::init(const Scene& scene) {
    device_ = gl::queryDeviceLimits();  // the particle pool is fitted to it
    // One sprite for every emitter that has one (one texture, one draw); a sprite that cannot be read
    // stops the run with its path.
    const ParticleEmitter* first = nullptr;
    for (const ParticleEmitter& e : scene.emitters) {
        if (e.sprite.empty()) continue;
        if (!first) {
            first = &e;
            spritePath_ = e.sprite.resolved;
            if (Status s = renderer_->loadSprite(spritePath_, spriteRows_); !s) return s;
        } else if (e.sprite.resolved != first->sprite.resolved) {
            log::warning("emitter '", e.name, "' asks for sprite ", e.sprite.path,
                         "; lesson 07 draws every emitter with ", first->sprite.path);
        }
    }
    return Status::success();
}

void FireLesson::update(const FrameInfo& frame) {
    // A frame with nothing to draw into (a minimised window) is not built, but the clock went on: its
    // time joins the next simulated step, so the fire comes back where it would have been.
    if (frame.size.empty()) pendingDt_ += frame.deltaSeconds;
}

void FireLesson::buildFrame(FrameGraph& graph, const FrameInfo& frame) {
    const int step = frame.step;
    HdrSceneTargets hdr = scenePass_->declare(graph, frame.world);
    // flip_sprite: the same file uploaded again, in the other row order.
    const auto spriteRows =
        flipSprite_ ? ParticleRenderer::SpriteRows::topFirst : ParticleRenderer::SpriteRows::bottomFirst;
    if (spriteRows != spriteRows_ && !spritePath_.empty()) {
        spriteRows_ = spriteRows;
        if (Status s = renderer_->loadSprite(spritePath_, spriteRows); !s)
            log::error("lesson 07: ", s.error());
    }
    const bool particles = !lacks(graph, SceneFeature::particles);

    // The simulation's setup follows the step and the parameters; a change starts it over. Without an
    // emitter in the scene nothing is made: no buffer, no dispatch.
    const Setup wanted = setupFor(frame);
    if (particles && (!configured_ || !(wanted == setup_))) {
        configure(wanted);
    } else if (particles && frame.benchmark) {
        restart();  // every bench frame of a setting draws the same picture, at a steady frame's cost
    }
    hitchNow_ = hitchOn(frame);
    // Added to what update() kept from frames that were not built: one longer step, as after a hitch.
    pendingDt_ += frame.deltaSeconds + (hitchNow_ ? double(hitch_) : 0.0);

    const std::string notInView = "every emitter's bounds are outside the view";
    const bool inView = particles && anyEmitterInView(frame);
    const Camera cam = frame.world.scene().camera;
    {
        PassGroup::Scope in(graph, particleGroup_);
        Pass& sim = graph.addPass("particles.simulate", [this, cam](PassContext&) {
            simulate(std::exchange(pendingDt_, 0.0), cam);
        });
        sim.keepAlive().setTaps(0);  // the simulation: buffers only

        // The pool in the inspector (particles.pool): one texel per slot. Nothing reads it, so the
        // graph runs this pass only when someone inspects or captures it.
        const int rows = std::max(1, int((system_.capacity() + 255) / 256));
        Pass& poolView = graph.addPass("particles.pool view", [this, rows](PassContext& ctx) {
            drawPoolView(GLuint(ctx.native(poolTexture_)), rows);
        });
        poolTexture_ =
            poolView.create("particles.pool", {TextureSize::absolute(256, rows), TextureFormat::RGBA32F, 1},
                            TextureUsage::Storage);
        poolView.setTaps(0);  // one texel per slot, from the pool's buffer

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
                           .colorMask = ColorMask{}})
                .setTaps(1);  // the sprite
            if (particles && !inView) drawPass.notCalledFor(notInView);
        } else {
            // Step 5: premultiplied particles into their own target (a fraction of the output), faded
            // by scene.depth read as a texture (no depth attachment: no feedback loop), then laid over
            // scene.color. The target is 32-bit float: additive light sums without limit there, and the
            // composite clamps it before the 16-bit scene.color.
            const int divisor = divisorOf(*offscreen_);
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
            off.setTaps(2);  // the sprite and the scene's depth (the soft fade)
            if (particles && !inView) off.notCalledFor(notInView);
            const FullscreenPass* composite = &*composite_;
            Pass& over =
                composite_->addPass(graph, "particles.composite", [composite, color](PassContext& ctx) {
                    glProgramUniform1f(composite->program(), glsl::kHdrMaxLocation, kSceneHdrMax);
                    composite->draw({GLuint(ctx.native(color))});
                });
            PassState state = FullscreenPass::state();
            state.blend = true;
            state.blendFunction = BlendFunction::premultipliedAlpha();
            over.read(color).modify(hdr.color, TextureUsage::ColorAttachment).setState(state).setTaps(1);
        }
    }

    // Lesson 06's bloom, the Shader effects chapter's chain, downstream of the particles.
    TextureHandle shown = hdr.color;
    {
        PassGroup::Scope in(graph, bloomGroup_);
        BloomChainSettings settings = shaderEffectsChain(threshold_, intensity_, 6);
        BloomChain::Declared d = chain_->declare(graph, hdr.color, settings);
        if (!d.empty()) {
            BloomCompositeSettings c{settings.filters, settings.upOffset,
                                     averagedCompositeScale(int(d.levels.size()))};
            DeclaredPass result = bloom_->declare(graph, hdr.color, d.glow(), c);
            if (!lacks(graph, SceneFeature::bloom)) shown = result.output;
        }
    }
    // Steps 1 and 2 clip like the chapter; from step 3 a filmic curve keeps the flame's colour.
    present_->declare(graph, shown, std::nullopt, step <= Hitch ? ToneCurve::clip : ToneCurve::filmic, 1.0f);
}

void FireLesson::drawPanel(const FrameInfo& frame) {
    switch (frame.step) {
        case Objects:
            ImGui::TextWrapped("%s", say("text.objects").c_str());
            break;
        case Hitch: {
            char seconds[32];
            std::snprintf(seconds, sizeof seconds, "%.2f", double(hitch_));
            ImGui::TextWrapped("%s", say("text.hitch", {{"seconds", seconds}}).c_str());
        } break;
        case Instanced:
            ImGui::TextWrapped("%s", say("text.instanced").c_str());
            break;
        case Gpu:
            ImGui::TextWrapped("%s", say("text.gpu").c_str());
            break;
        default:
            ImGui::TextWrapped("%s", say("text.offscreen").c_str());
            break;
    }
}

void FireLesson::facts(Facts& out, const FrameInfo& frame) const {
    if (frame.world.scene().emitters.empty()) {
        out.add("particles", say("text.none"));
        out.addAs("poolBytes", "poolBytesNoEmitter", "0");
        return;
    }
    if (!configured_) return;
    out.add("path", kPathNames[int(setup_.path)]);
    out.add("drawCalls", std::to_string(drawCalls_));
    std::uint32_t live = system_.liveCount();
    std::uint64_t replaced = system_.replacedCount();
    if (setup_.path == Path::gpu && gpu_ && !frame.benchmark) {
        GpuParticleStats stats = gpu_->readStats();
        live = stats.live;
        replaced = stats.replaced;
    }
    out.add("live", std::to_string(live));
    out.add("capacity", std::to_string(system_.capacity()));
    out.add("particleBudget", budget_.summary());
    out.add("replaced", std::to_string(replaced));
    out.add("dropped", std::to_string(system_.droppedCount()));
    // CPU time inside the calls: on a software renderer that holds the driver's own work too.
    out.add("simulateCpuMs", cat(simulateMs_));
    out.add("drawCpuMs", cat(drawCpuMs_));
    out.add("spawnedLastFrame", std::to_string(system_.spawnedLastFrame()));
    std::uint64_t bytes = setup_.path == Path::gpu ? (gpu_ ? gpu_->bytes() : 0) : renderer_->instanceBytes();
    out.add("poolBytes", std::to_string(bytes));
    out.add(
        "buffers",
        setup_.path == Path::gpu
            ? "particles.pool, particles.live, particles.draw_command, particles.stats, particles.emitters"
        : setup_.path == Path::instanced ? "particles.instances, particles.emitters"
                                         : "particles.emitters (and one set of uniforms per particle)");
    if (frame.step == Hitch) {
        out.add("hitch", hitchNow_);
        out.add("negativeAlpha", std::to_string(negativeAlpha_));
        std::uint32_t chapterBacklog = 0;
        for (std::size_t e = 0; e < system_.clocks().size(); ++e) {
            if (system_.setups()[e].rules.chapterTimer)
                chapterBacklog +=
                    std::uint32_t(system_.clocks()[e].backlog() * system_.setups()[e].emitter.ratePerSecond);
        }
        out.add("chapterBacklog", std::to_string(chapterBacklog));
    }
    if (frame.step == Objects && !setup_.emitters.empty()) {
        // The first emitter: the chapter's fire (the scene's first emitter, or the particle hold_alpha
        // holds).
        const glm::vec4 c = setup_.emitters.front().emitter.startColor;
        // An opaque particle shows its emission, clipped at 1 and encoded as sRGB bytes (what step 1
        // displays where the flame is opaque, with the bloom's intensity at 0).
        auto shown = [](float v) { return int(toDisplayValue(v, ViewTransform::LinearToSrgb)); };
        out.add("opaqueFlame", cat("(", shown(c.r), ", ", shown(c.g), ", ", shown(c.b), ")"));
        if (holdingAlpha(frame)) {
            // The bright pass keeps what its brightest channel has above the threshold.
            const float brightest = std::max({c.r, c.g, c.b}) * holdAlpha_;
            out.add("heldBrightest", cat(brightest));
            out.add("heldGlows", brightest > threshold_ ? "yes" : "no");
        }
    }
    if (frame.step <= Instanced) out.add("outOfOrder", std::to_string(outOfOrder_));
    if (frame.previousFrame) {
        out.add("particlesMs", cat(particleGroup_.timeMs(*frame.previousFrame)));
        out.add("frameMs", cat(frame.previousFrame->timedMs()));
    }
}

}  // namespace lesson07

FX_LESSON(lesson07::FireLesson, "Fire emitter", "scenes/07_fire_emitter.json")
