// Simulate and draw only what the scene calls for. A small lesson-shaped frame graph built with SceneWork
// runs on the real GL executor and texture pool; for each feature, the same scene with and without it
// must run the expected passes, allocate the expected texture bytes, and call the expected updates.
#include <algorithm>
#include <functional>
#include <string>
#include <vector>
#include "base/paths.hpp"

#include "effects/scene/scene_work.hpp"
#include "gl_test.hpp"
#include "render/frame_graph.hpp"
#include "render/texture_pool.hpp"
#include "render_gl/gl_pass_executor.hpp"
#include "render_gl/gl_texture_allocator.hpp"
#include "render_gl/pass_timer.hpp"
#include "scene/scene_loader.hpp"

using namespace fx;

namespace {

constexpr Size2D kOutput{64, 48};
constexpr int kShadowMapSize = 256;

// The per-feature textures of the test lesson, and their bytes at kOutput.
const TextureDesc kShadowMap{TextureSize::absolute(kShadowMapSize, kShadowMapSize), TextureFormat::Depth32F,
                             1};
const TextureDesc kHalfHdr{TextureSize::outputFraction(1, 2), TextureFormat::RGBA16F, 1};
const TextureDesc kHdr{TextureSize::output(), TextureFormat::RGBA16F, 1};
const TextureDesc kDepth{TextureSize::output(), TextureFormat::Depth32F, 1};
const TextureDesc kBloomChain{TextureSize::outputFraction(1, 2), TextureFormat::RGBA16F, kFullMipChain};

std::uint64_t bytesOf(const TextureDesc& desc) {
    return textureBytes(resolve(desc, kOutput));
}

// What a lesson would declare: every pass, each gated by the feature it exists for.
struct TestLesson {
    SceneWork work;
    std::vector<std::string> bodiesRun;

    void build(FrameGraph& graph) {
        auto body = [this](const char* name) {
            return [this, name](PassContext&) { bodiesRun.push_back(name); };
        };
        auto sceneColor = graph.declareTexture("scene.color", kHdr);
        auto sceneDepth = graph.declareTexture("scene.depth", kDepth);

        // Skinning writes buffers the graph does not track, so it is kept alive, and gated.
        needs(graph.addPass("skinning", body("skinning")).keepAlive(), SceneFeature::skinnedMeshes);

        auto shadowMap = graph.declareTexture("shadow.map", kShadowMap);
        needs(graph.addPass("shadow map", body("shadow map")).writeDepth(shadowMap), SceneFeature::shadows);

        auto& scene = graph.addPass("scene", body("scene")).writeColor(sceneColor).writeDepth(sceneDepth);
        if (work.has(SceneFeature::shadows)) scene.read(shadowMap);  // a shadow map exists only with shadows

        auto& clouds = graph.addPass("clouds", body("clouds"));
        auto cloudColor = clouds.create("clouds.color", kHalfHdr, TextureUsage::ColorAttachment);
        clouds.read(sceneDepth);
        needs(clouds, SceneFeature::clouds);
        needs(graph.addPass("clouds composite", body("clouds composite"))
                  .read(cloudColor)
                  .modify(sceneColor, TextureUsage::ColorAttachment),
              SceneFeature::clouds);

        auto& particles = graph.addPass("particles", body("particles"));
        auto particleColor = particles.create("particles.color", kHalfHdr, TextureUsage::ColorAttachment);
        particles.read(sceneDepth);
        needs(particles, SceneFeature::particles);
        needs(graph.addPass("particles composite", body("particles composite"))
                  .read(particleColor)
                  .modify(sceneColor, TextureUsage::ColorAttachment),
              SceneFeature::particles);

        auto& bloom = graph.addPass("bloom", body("bloom"));
        auto bloomChain = bloom.create("bloom.chain", kBloomChain, TextureUsage::ColorAttachment);
        bloom.read(sceneColor);
        needs(bloom, SceneFeature::bloom);

        auto& tonemap = graph.addPass("tonemap", body("tonemap")).read(sceneColor).writeColor(graph.output());
        if (work.has(SceneFeature::bloom)) tonemap.read(bloomChain);
    }
};

struct FrameResult {
    std::vector<std::string> executed;  // in execution order
    std::uint64_t allocatedBytes = 0;   // transient textures that got GL textures
    FrameReport report;
    std::vector<std::string> bodiesRun;
    std::vector<std::string> updatesRun;
};

Scene baseScene() {
    auto scene = parseScene(R"({"name": "base", "camera": {"position": [0, 2, 8], "target": [0, 0, 0]},
        "lights": [{"type": "directional", "direction": [0, -1, 0]}],
        "objects": [{"name": "ground", "primitive": {"shape": "plane"}}]})",
                            "base.json", {fx::projectRoot() / "res", false});
    EXPECT_TRUE(scene.ok()) << (scene.ok() ? "" : scene.error());
    return scene.ok() ? *scene : Scene{};
}

}  // namespace

class SceneWorkGraph : public GlTest {
protected:
    FrameResult run(const Scene& scene) {
        GlTextureAllocator allocator;
        TexturePool pool(allocator);
        PassTimer timer(TimingMode::Off, "");
        GlPassExecutor executor(timer, {context().presentFramebuffer(), true});
        TestLesson lesson{SceneWork(scene), {}};
        FrameResult result;
        // Simulations: registered for everything, run only for what the scene has.
        lesson.work.onUpdate(Simulation::animation, "animation",
                             [&](const SimulationStep&) { result.updatesRun.push_back("animation"); });
        lesson.work.onUpdate(Simulation::particles, "particles",
                             [&](const SimulationStep&) { result.updatesRun.push_back("particles"); });
        lesson.work.onUpdate(Simulation::clouds, "clouds",
                             [&](const SimulationStep&) { result.updatesRun.push_back("clouds"); });
        lesson.work.update(1.0, 1.0 / 60.0);

        FrameGraph graph(OutputTarget{kOutput, "output", TextureFormat::RGBA8, 0});
        lesson.work.describeTo(graph);  // what the runner does before a lesson declares
        lesson.build(graph);
        Status status = graph.execute(pool, executor);
        EXPECT_TRUE(status.ok()) << status.error();
        result.report = graph.report();
        for (const auto& p : result.report.passes)
            if (p.executed) result.executed.push_back(p.name);
        for (const auto& t : result.report.textures)
            if (t.allocated) result.allocatedBytes += t.bytes;
        EXPECT_EQ(result.report.pool.liveBytes, result.allocatedBytes) << "the pool holds exactly what ran";
        result.bodiesRun = lesson.bodiesRun;
        graph.releaseTextures();
        pool.endFrame();
        return result;
    }

    void expectNotCalledFor(const FrameResult& r, const std::string& pass, const std::string& reason) {
        const PassRecord* record = r.report.findPass(pass);
        ASSERT_NE(record, nullptr) << pass;
        EXPECT_EQ(record->status, PassStatus::NotCalledFor) << pass;
        EXPECT_EQ(record->reason, reason) << pass;
        EXPECT_FALSE(record->executed) << pass;
    }
};

TEST_F(SceneWorkGraph, APlainSceneRunsOnlyTheScenePasses) {
    FrameResult r = run(baseScene());
    EXPECT_EQ(r.executed, (std::vector<std::string>{"scene", "tonemap"}));
    EXPECT_EQ(r.bodiesRun, r.executed);
    EXPECT_EQ(r.allocatedBytes, bytesOf(kHdr) + bytesOf(kDepth));
    EXPECT_TRUE(r.updatesRun.empty());
    expectNotCalledFor(r, "particles", "scene has no particle emitter");
    expectNotCalledFor(r, "particles composite", "scene has no particle emitter");
    expectNotCalledFor(r, "clouds", "scene has no cloud layer");
    expectNotCalledFor(r, "shadow map", "scene has no light that casts shadows");
    const TextureRecord* particles = r.report.findTexture("particles.color");
    ASSERT_NE(particles, nullptr);
    EXPECT_FALSE(particles->allocated);
    EXPECT_EQ(particles->reason, "scene has no particle emitter");
}

struct FeatureCase {
    const char* name;
    SceneFeature feature;
    std::function<void(Scene&)> add;
    std::vector<std::string> executedWith;  // the whole pass list with the feature present
    std::uint64_t extraBytes;               // what the feature's textures cost
    std::vector<std::string> updatesWith;
};

TEST_F(SceneWorkGraph, EachFeatureAddsExactlyItsPassesTexturesAndUpdates) {
    const Scene base = baseScene();
    const FrameResult without = run(base);
    const std::uint64_t baseBytes = bytesOf(kHdr) + bytesOf(kDepth);
    const SceneFeatures baseFeatures = features(base);

    std::vector<FeatureCase> cases = {
        {"particles",
         SceneFeature::particles,
         [](Scene& s) { s.emitters.push_back(ParticleEmitter{}); },
         {"scene", "particles", "particles composite", "tonemap"},
         bytesOf(kHalfHdr),
         {"particles"}},
        {"clouds",
         SceneFeature::clouds,
         [](Scene& s) { s.clouds.push_back(CloudLayer{}); },
         {"scene", "clouds", "clouds composite", "tonemap"},
         bytesOf(kHalfHdr),
         {"clouds"}},
        {"shadows",
         SceneFeature::shadows,
         [](Scene& s) { s.lights[0].shadow.casts = true; },
         {"shadow map", "scene", "tonemap"},
         bytesOf(kShadowMap),
         {}},
        {"bloom",
         SceneFeature::bloom,
         [](Scene& s) { s.postEffects.bloom = BloomSettings{}; },
         {"scene", "bloom", "tonemap"},
         bytesOf(kBloomChain),
         {}},
        {"skinned meshes",
         SceneFeature::skinnedMeshes,
         [](Scene& s) {
             SceneObject character;
             character.name = "character";
             character.gltf.path = "../models/character.gltf";
             character.animation.clips = {"walk"};
             character.skinned = true;
             s.objects.push_back(character);
         },
         {"skinning", "scene", "tonemap"},
         0,
         {"animation"}},
    };
    for (const FeatureCase& c : cases) {
        SCOPED_TRACE(c.name);
        Scene with = base;
        c.add(with);
        ASSERT_TRUE(features(with).has(c.feature));
        ASSERT_FALSE(baseFeatures.has(c.feature));
        FrameResult r = run(with);
        EXPECT_EQ(r.executed, c.executedWith);
        EXPECT_EQ(r.bodiesRun, r.executed);
        EXPECT_EQ(r.allocatedBytes, baseBytes + c.extraBytes);
        EXPECT_EQ(r.updatesRun, c.updatesWith);
        // Without it: the feature's passes are listed, not run, and say why.
        for (const auto& pass : c.executedWith) {
            if (std::find(without.executed.begin(), without.executed.end(), pass) != without.executed.end())
                continue;
            expectNotCalledFor(without, pass, baseFeatures.missingReason(c.feature));
        }
    }
    EXPECT_EQ(without.allocatedBytes, baseBytes);
}

TEST(SceneWork, RecordsWhyEachSimulationDidNotRun) {
    SceneWork work(SceneFeatures{});
    int calls = 0;
    work.onUpdate(Simulation::particles, "fire", [&](const SimulationStep&) { ++calls; });
    work.onUpdate(Simulation::motion, "orbit", [&](const SimulationStep&) { ++calls; });
    work.update(10.0, 0.5);
    EXPECT_EQ(calls, 0);
    ASSERT_EQ(work.lastUpdate().size(), 2u);
    EXPECT_FALSE(work.lastUpdate()[0].ran);
    EXPECT_EQ(work.lastUpdate()[0].reason, "scene has no particle emitter");
    EXPECT_EQ(work.lastUpdate()[1].reason, "scene has no moving object");
    EXPECT_TRUE(work.ranLastUpdate().empty());

    SceneFeatures some;
    some.movingObjects = 2;
    SceneWork moving(some);
    SimulationStep seen;
    moving.onUpdate(Simulation::motion, "orbit", [&](const SimulationStep& s) { seen = s; });
    moving.update(10.0, 0.5);
    EXPECT_EQ(moving.ranLastUpdate(), std::vector<std::string>{"orbit"});
    EXPECT_EQ(seen.seconds, 10.0);
    EXPECT_EQ(seen.deltaSeconds, 0.5);
}
