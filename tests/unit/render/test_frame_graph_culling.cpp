#include <gtest/gtest.h>

#include "fake_gpu.hpp"
#include "render/frame_graph.hpp"

namespace fx {
namespace {

using test::names;
using Names = std::vector<std::string>;

const TextureDesc kHdr{TextureSize::output(), TextureFormat::RGBA16F};

// scene -> bloom -> composite -> output, plus a debug view nobody looks at.
struct BloomFrame {
    FrameGraph graph{{.size = {1280, 720}}};
    TextureHandle color = graph.declareTexture("scene.color", kHdr);
    TextureHandle bloom =
        graph.declareTexture("bloom.result", {TextureSize::outputFraction(1, 2), TextureFormat::RGBA16F});
    TextureHandle normals =
        graph.declareTexture("debug.normals", {TextureSize::output(), TextureFormat::RGBA8});
    Pass& scene = graph.addPass("scene").writeColor(color);
    Pass& bloomPass = graph.addPass("bloom").read(color).writeColor(bloom);
    Pass& composite = graph.addPass("composite").read(color).read(bloom).writeColor(graph.output());
    Pass& debug = graph.addPass("show normals").read(color).writeColor(normals);

    const PassRecord& record(const std::string& name) {
        const PassRecord* r = graph.report().findPass(name);
        EXPECT_NE(r, nullptr) << name;
        static const PassRecord kNone;
        return r ? *r : kNone;
    }
};

TEST(FrameGraphCulling, APassWhoseOutputReachesNothingIsCulledAndSaysWhat) {
    BloomFrame f;
    ASSERT_TRUE(f.graph.compile().ok());
    EXPECT_EQ(names(f.graph, f.graph.executionOrder()), (Names{"scene", "bloom", "composite"}));
    const PassRecord& debug = f.record("show normals");
    EXPECT_EQ(debug.status, PassStatus::OutputUnused);
    EXPECT_EQ(debug.reason, "output unused: 'debug.normals' reaches no output, capture or inspected view");
    // The report lists passes that run first, in execution order, then the others.
    ASSERT_EQ(f.graph.report().passes.size(), 4u);
    EXPECT_EQ(f.graph.report().passes[3].name, "show normals");
}

TEST(FrameGraphCulling, CullingCascadesUpAnUnusedChain) {
    FrameGraph graph({.size = {1280, 720}});
    auto color = graph.declareTexture("scene.color", kHdr);
    auto blurred = graph.declareTexture("blur.h", kHdr);
    auto blurred2 = graph.declareTexture("blur.v", kHdr);
    graph.addPass("scene").writeColor(color).writeColor(graph.declareTexture("scene.normals", kHdr));
    graph.addPass("blur h").read(color).writeColor(blurred);
    graph.addPass("blur v").read(blurred).writeColor(blurred2);
    graph.addPass("present").read(color).writeColor(graph.output());
    ASSERT_TRUE(graph.compile().ok());
    EXPECT_EQ(names(graph, graph.executionOrder()), (Names{"scene", "present"}));
    EXPECT_EQ(graph.report().findPass("blur h")->reason,
              "output unused: 'blur.h' reaches no output, capture or inspected view");
    EXPECT_EQ(graph.report().findPass("blur v")->status, PassStatus::OutputUnused);
}

TEST(FrameGraphCulling, InspectingATextureBringsItsProducersBack) {
    FrameGraph graph({.size = {1280, 720}});
    auto color = graph.declareTexture("scene.color", kHdr);
    auto blurred = graph.declareTexture("blur.h", kHdr);
    auto blurred2 = graph.declareTexture("blur.v", kHdr);
    graph.addPass("scene").writeColor(color);
    graph.addPass("blur h").read(color).writeColor(blurred);
    graph.addPass("blur v").read(blurred).writeColor(blurred2);
    graph.addPass("present").read(color).writeColor(graph.output());
    graph.inspect("blur.v");
    ASSERT_TRUE(graph.compile().ok());
    EXPECT_EQ(names(graph, graph.executionOrder()), (Names{"scene", "blur h", "blur v", "present"}));
    EXPECT_TRUE(graph.report().findTexture("blur.v")->inspected);
}

TEST(FrameGraphCulling, InspectingAnUnknownNameIsReportedNotFatal) {
    BloomFrame f;
    f.graph.inspect("bloom.down[9]");
    ASSERT_TRUE(f.graph.compile().ok());
    EXPECT_EQ(f.graph.report().unknownTargets, (Names{"bloom.down[9]"}));
}

TEST(FrameGraphCulling, CaptureIsARootToo) {
    BloomFrame f;
    f.graph.capture(f.normals);
    ASSERT_TRUE(f.graph.compile().ok());
    EXPECT_EQ(f.record("show normals").status, PassStatus::Runs);
    EXPECT_TRUE(f.graph.report().findTexture("debug.normals")->captured);
}

TEST(FrameGraphCulling, ADisabledProducerCascadesItsReasonToConsumers) {
    BloomFrame f;
    f.bloomPass.disable("disabled in step 2");
    ASSERT_TRUE(f.graph.compile().ok());
    EXPECT_EQ(f.record("bloom").status, PassStatus::Disabled);
    EXPECT_EQ(f.record("bloom").reason, "disabled in step 2");
    EXPECT_EQ(f.record("composite").status, PassStatus::MissingInput);
    EXPECT_EQ(f.record("composite").reason,
              "needs 'bloom.result', which pass 'bloom' did not produce ('bloom': disabled in step 2)");
    // Nothing reaches the output any more, so the scene pass goes too, for its own reason.
    EXPECT_EQ(f.record("scene").status, PassStatus::OutputUnused);
    EXPECT_TRUE(f.graph.executionOrder().empty());
}

TEST(FrameGraphCulling, MissingInputsNestAlongAChain) {
    FrameGraph graph({.size = {320, 240}});
    auto a = graph.declareTexture("a", kHdr);
    auto b = graph.declareTexture("b", kHdr);
    graph.addPass("P").writeColor(a).notCalledFor("scene has no cloud layer");
    graph.addPass("Q").read(a).writeColor(b);
    graph.addPass("R").read(b).writeColor(graph.output());
    ASSERT_TRUE(graph.compile().ok());
    EXPECT_EQ(graph.report().findPass("P")->status, PassStatus::NotCalledFor);
    EXPECT_EQ(graph.report().findPass("R")->reason,
              "needs 'b', which pass 'Q' did not produce ('Q': needs 'a', which pass 'P' did not produce "
              "('P': scene has no cloud layer))");
}

TEST(FrameGraphCulling, APassTheSceneDoesNotCallForLeavesTheRestRunning) {
    FrameGraph graph({.size = {1280, 720}});
    auto color = graph.declareTexture("scene.color", kHdr);
    graph.addPass("scene").writeColor(color);
    graph.addPass("particles")
        .modify(color, TextureUsage::ColorAttachment)
        .notCalledFor("scene has no particle emitter");
    graph.addPass("tonemap").read(color).writeColor(graph.output());
    ASSERT_TRUE(graph.compile().ok());
    EXPECT_EQ(names(graph, graph.executionOrder()), (Names{"scene", "tonemap"}));
    EXPECT_EQ(graph.report().findPass("particles")->status, PassStatus::NotCalledFor);
    EXPECT_EQ(graph.report().findPass("particles")->reason, "scene has no particle emitter");
}

TEST(FrameGraphCulling, SwitchedOffPassesNeverRunEvenWhenTheirOutputIsARoot) {
    FrameGraph graph({.size = {1280, 720}});
    auto color = graph.declareTexture("scene.color", kHdr);
    graph.addPass("scene").writeColor(color).disable("disabled in step 1");
    graph.addPass("present").read(color).writeColor(graph.output()).disable("disabled in step 1");
    graph.inspect("scene.color");
    ASSERT_TRUE(graph.compile().ok());
    EXPECT_TRUE(graph.executionOrder().empty());
    EXPECT_EQ(graph.report().findPass("present")->status, PassStatus::Disabled);
    EXPECT_EQ(graph.report().findPass("scene")->reason, "disabled in step 1");
}

TEST(FrameGraphCulling, DisabledWithoutAReasonStillSaysSomething) {
    FrameGraph graph({.size = {8, 8}});
    graph.addPass("a").writeColor(graph.output()).disable("");
    graph.addPass("b").writeColor(graph.declareTexture("t", kHdr)).notCalledFor("");
    ASSERT_TRUE(graph.compile().ok());
    EXPECT_EQ(graph.report().findPass("a")->reason, "disabled");
    EXPECT_EQ(graph.report().findPass("b")->reason, "not called for by the scene");
}

TEST(FrameGraphCulling, AStepMaySwapOneCreatorForAnother) {
    FrameGraph graph({.size = {1280, 720}});
    auto blurred = graph.declareTexture("blur", kHdr);
    graph.addPass("naive blur").writeColor(blurred).disable("disabled in step 2");
    graph.addPass("separable blur").writeColor(blurred);
    graph.addPass("present").read(blurred).writeColor(graph.output());
    ASSERT_TRUE(graph.compile().ok()) << graph.errors().front();
    EXPECT_EQ(names(graph, graph.executionOrder()), (Names{"separable blur", "present"}));
    EXPECT_EQ(graph.report().findTexture("blur")->producer, "separable blur");
}

TEST(FrameGraphCulling, WritingAnImportKeepsAPassAlive) {
    FrameGraph graph({.size = {1280, 720}});
    auto history = graph.importTexture("taa.history", {1280, 720, TextureFormat::RGBA16F, 1}, 77);
    auto previous = graph.importTexture("taa.previous", {1280, 720, TextureFormat::RGBA16F, 1}, 78);
    graph.addPass("resolve").read(previous).writeColor(history);
    ASSERT_TRUE(graph.compile().ok());
    EXPECT_EQ(names(graph, graph.executionOrder()), (Names{"resolve"}));
}

TEST(FrameGraphCulling, KeepAliveRunsAPassWithoutReaders) {
    FrameGraph graph({.size = {1280, 720}});
    graph.addPass("update particles").keepAlive();
    graph.addPass("unused").writeColor(graph.declareTexture("t", kHdr));
    graph.addPass("nothing");
    ASSERT_TRUE(graph.compile().ok());
    EXPECT_EQ(names(graph, graph.executionOrder()), (Names{"update particles"}));
    EXPECT_EQ(graph.report().findPass("nothing")->reason, "output unused: it declares no outputs");
}

TEST(FrameGraphCulling, CulledTexturesCarryTheirProducersReason) {
    BloomFrame f;
    f.bloomPass.disable("disabled in step 2");
    f.graph.inspect("scene.color");
    ASSERT_TRUE(f.graph.compile().ok());
    const TextureRecord* bloom = f.graph.report().findTexture("bloom.result");
    ASSERT_NE(bloom, nullptr);
    EXPECT_EQ(bloom->producer, "bloom");
    EXPECT_EQ(bloom->reason, "disabled in step 2");
    EXPECT_EQ(bloom->bytes, 640u * 360u * 8u);
    EXPECT_EQ(f.graph.report().findTexture("debug.normals")->reason,
              "output unused: 'debug.normals' reaches no output, capture or inspected view");
}

}  // namespace
}  // namespace fx

namespace fx {
namespace {

TEST(FrameGraphCulling, AModifierThatRunsKeepsTheCreatorOfWhatItModifies) {
    // Nothing reads the accumulation buffer after "splat", but splat reads it, so it must be cleared.
    FrameGraph graph({.size = {1280, 720}});
    auto accum = graph.declareTexture("particles.accum", {TextureSize::output(), TextureFormat::R32F});
    graph.addPass("splat").modify(accum, TextureUsage::Storage).writeColor(graph.output());
    graph.addPass("clear accum").writeStorage(accum);
    ASSERT_TRUE(graph.compile().ok());
    EXPECT_EQ(test::names(graph, graph.executionOrder()), (std::vector<std::string>{"clear accum", "splat"}));
}

}  // namespace
}  // namespace fx
