#include <gtest/gtest.h>

#include <map>

#include "base/log.hpp"
#include "fake_gpu.hpp"
#include "render/frame_graph.hpp"

namespace fx {
namespace {

using test::FakeAllocator;
using test::RecordingExecutor;
using Names = std::vector<std::string>;

const TextureDesc kHdr{TextureSize::output(), TextureFormat::RGBA16F};
constexpr std::uint64_t kHdrBytes = 1280u * 720u * 8u;

// Which texture each body saw, by resource name.
using Seen = std::map<std::string, NativeTexture>;

// scene -> a -> b -> c -> output: a, b and c have one key; a is dead once b is written, so c can
// take a's texture. "debug" is culled and must allocate nothing.
void declareChain(FrameGraph& graph, Seen& seen) {
    auto scene = graph.declareTexture("scene.color", kHdr);
    auto a = graph.declareTexture("blur.a", kHdr);
    auto b = graph.declareTexture("blur.b", kHdr);
    auto c = graph.declareTexture("blur.c", kHdr);
    auto debug =
        graph.declareTexture("debug.big", {TextureSize::absolute(4096, 4096), TextureFormat::RGBA32F});
    auto remember = [&seen](TextureHandle h) {
        return [&seen, h](PassContext& ctx) { seen[ctx.texture(h).name] = ctx.native(h); };
    };
    graph.addPass("scene", remember(scene)).writeColor(scene);
    graph.addPass("blur 1", remember(a)).read(scene).writeColor(a);
    graph.addPass("blur 2", remember(b)).read(a).writeColor(b);
    graph.addPass("blur 3", remember(c)).read(b).writeColor(c);
    graph.addPass("present").read(c).read(scene).writeColor(graph.output());
    graph.addPass("debug", remember(debug)).read(scene).writeColor(debug);
}

TEST(FrameGraphExecute, RunsPassesInOrderThroughTheExecutorHooks) {
    FakeAllocator gpu;
    TexturePool pool(gpu);
    RecordingExecutor executor;
    Seen seen;
    FrameGraph graph({.size = {1280, 720}});
    declareChain(graph, seen);
    ASSERT_TRUE(graph.execute(pool, executor).ok());
    Names order{"scene", "blur 1", "blur 2", "blur 3", "present"};
    EXPECT_EQ(executor.begun, order);
    EXPECT_EQ(executor.ended, order);
    EXPECT_TRUE(executor.frameBegun);
    EXPECT_TRUE(executor.frameEnded);
    const FrameReport& report = graph.report();
    for (std::size_t i = 0; i < order.size(); ++i) {
        EXPECT_EQ(report.passes[i].name, order[i]);
        EXPECT_TRUE(report.passes[i].executed);
        EXPECT_EQ(report.passes[i].timeMs, 0.25);
        EXPECT_EQ(report.passes[i].timingMethod, "fake clock");
    }
    EXPECT_FALSE(report.findPass("debug")->executed);
    EXPECT_FALSE(report.findPass("debug")->timeMs.has_value());
    ASSERT_EQ(report.findPass("present")->reads.size(), 2u);
    EXPECT_EQ(report.findPass("present")->reads[0].texture, "blur.c");
    EXPECT_EQ(report.findPass("present")->writes[0].texture, "output");
    EXPECT_TRUE(graph.pass(4).writesPresentedOutput());
    EXPECT_FALSE(graph.pass(3).writesPresentedOutput());
}

TEST(FrameGraphExecute, DisjointLifetimesShareOneTextureWithinAFrame) {
    FakeAllocator gpu;
    TexturePool pool(gpu);
    RecordingExecutor executor;
    Seen seen;
    FrameGraph graph({.size = {1280, 720}});
    declareChain(graph, seen);
    ASSERT_TRUE(graph.execute(pool, executor).ok());
    // scene.color lives to the end; a and b overlap; c reuses a.
    EXPECT_EQ(gpu.created.size(), 3u);
    EXPECT_EQ(seen["blur.c"], seen["blur.a"]);
    EXPECT_NE(seen["blur.b"], seen["blur.a"]);
    EXPECT_NE(seen["scene.color"], seen["blur.a"]);
    // The reused texture carries both resources' names for debuggers, true for every pass that uses it.
    ASSERT_EQ(gpu.relabelled.size(), 1u);
    EXPECT_EQ(gpu.relabelled[0], (std::pair<NativeTexture, std::string>{seen["blur.a"], "blur.a | blur.c"}));
    EXPECT_EQ(pool.peakBytes(), 3 * kHdrBytes);
}

TEST(FrameGraphExecute, TexturesArriveBeforeTheirFirstWriterAndLeaveAfterTheirLastReader) {
    FakeAllocator gpu;
    TexturePool pool(gpu);
    RecordingExecutor executor;
    executor.pool = &pool;
    Seen seen;
    FrameGraph graph({.size = {1280, 720}});
    declareChain(graph, seen);
    ASSERT_TRUE(graph.execute(pool, executor).ok());
    // In use at each beginPass: scene | scene+a | scene+a+b | scene+b+c | scene+c.
    EXPECT_EQ(executor.inUseAtBegin, (std::vector<std::uint64_t>{kHdrBytes, 2 * kHdrBytes, 3 * kHdrBytes,
                                                                 3 * kHdrBytes, 2 * kHdrBytes}));
    EXPECT_EQ(pool.inUseBytes(), 0u);  // all handed back after the last reader
    EXPECT_EQ(graph.texture(*graph.findTexture("blur.c")).native, 0u);
}

TEST(FrameGraphExecute, ACulledPassAllocatesNothing) {
    FakeAllocator gpu;
    TexturePool pool(gpu);
    RecordingExecutor executor;
    Seen seen;
    FrameGraph graph({.size = {1280, 720}});
    declareChain(graph, seen);
    ASSERT_TRUE(graph.execute(pool, executor).ok());
    for (const auto& c : gpu.created) EXPECT_NE(c.label, "debug.big");
    EXPECT_EQ(seen.count("debug.big"), 0u);
    const TextureRecord* debug = graph.report().findTexture("debug.big");
    ASSERT_NE(debug, nullptr);
    EXPECT_FALSE(debug->allocated);
    EXPECT_EQ(debug->producer, "debug");
    EXPECT_EQ(debug->bytes, 4096u * 4096u * 16u);
    EXPECT_EQ(debug->reason, "output unused: 'debug.big' reaches no output, capture or inspected view");
    EXPECT_TRUE(graph.report().findTexture("blur.a")->allocated);
    EXPECT_EQ(graph.report().pool.liveBytes, 3 * kHdrBytes);
}

TEST(FrameGraphExecute, ASecondIdenticalFrameCreatesNothing) {
    FakeAllocator gpu;
    TexturePool pool(gpu);
    RecordingExecutor executor;
    Seen first;
    Seen second;
    {
        FrameGraph graph({.size = {1280, 720}});
        declareChain(graph, first);
        ASSERT_TRUE(graph.execute(pool, executor).ok());
    }
    pool.endFrame();
    std::size_t created = gpu.created.size();
    {
        FrameGraph graph({.size = {1280, 720}});
        declareChain(graph, second);
        ASSERT_TRUE(graph.execute(pool, executor).ok());
    }
    pool.endFrame();
    EXPECT_EQ(gpu.created.size(), created);
    EXPECT_TRUE(gpu.destroyed.empty());
    EXPECT_EQ(first, second);  // each resource keeps its texture from frame to frame
}

TEST(FrameGraphExecute, TexturesAStepNoLongerUsesAreFreedAfterNFrames) {
    FakeAllocator gpu;
    TexturePool pool(gpu, 2);
    RecordingExecutor executor;
    Seen seen;
    {
        FrameGraph graph({.size = {1280, 720}});
        declareChain(graph, seen);
        ASSERT_TRUE(graph.execute(pool, executor).ok());
    }
    pool.endFrame();
    auto quieterFrame = [&] {
        FrameGraph graph({.size = {1280, 720}});
        auto scene = graph.declareTexture("scene.color", kHdr);
        graph.addPass("scene").writeColor(scene);
        graph.addPass("present").read(scene).writeColor(graph.output());
        ASSERT_TRUE(graph.execute(pool, executor).ok());
        pool.endFrame();
    };
    quieterFrame();
    EXPECT_TRUE(gpu.destroyed.empty());
    quieterFrame();
    EXPECT_EQ(gpu.destroyed.size(), 2u);  // the two blur textures; scene.color is still in use
    EXPECT_EQ(pool.liveBytes(), kHdrBytes);
}

TEST(FrameGraphExecute, AResizeAllocatesTheNewSizeAndEvictsTheOld) {
    FakeAllocator gpu;
    TexturePool pool(gpu, 1);
    RecordingExecutor executor;
    for (Size2D size : {Size2D{1280, 720}, Size2D{1279, 719}}) {
        FrameGraph graph({.size = size});
        auto quarter = graph.declareTexture(
            "bloom.down[2]", {TextureSize::outputFraction(1, 4), TextureFormat::RGBA16F, kFullMipChain});
        graph.addPass("down").writeColor(quarter);
        graph.addPass("present").read(quarter).writeColor(graph.output());
        ASSERT_TRUE(graph.execute(pool, executor).ok());
        pool.endFrame();
    }
    ASSERT_EQ(gpu.created.size(), 2u);
    EXPECT_EQ(gpu.created[1].spec, (TextureSpec{319, 179, TextureFormat::RGBA16F, 9}));
    EXPECT_EQ(gpu.destroyed.size(), 1u);
    EXPECT_EQ(pool.liveBytes(), textureBytes({319, 179, TextureFormat::RGBA16F, 9}));
}

TEST(FrameGraphExecute, InspectedTexturesStayHeldUntilReleased) {
    FakeAllocator gpu;
    TexturePool pool(gpu);
    RecordingExecutor executor;
    Seen seen;
    FrameGraph graph({.size = {1280, 720}});
    declareChain(graph, seen);
    graph.inspect("blur.a");
    ASSERT_TRUE(graph.execute(pool, executor).ok());
    // blur.a cannot be reused for blur.c while the overlay still shows it.
    EXPECT_EQ(gpu.created.size(), 4u);
    EXPECT_EQ(graph.texture(*graph.findTexture("blur.a")).native, seen["blur.a"]);
    EXPECT_EQ(pool.inUseBytes(), kHdrBytes);
    graph.releaseTextures();
    EXPECT_EQ(pool.inUseBytes(), 0u);
    EXPECT_EQ(graph.texture(*graph.findTexture("blur.a")).native, 0u);
}

TEST(FrameGraphExecute, DestroyingTheGraphHandsRetainedTexturesBack) {
    FakeAllocator gpu;
    TexturePool pool(gpu);
    RecordingExecutor executor;
    Seen seen;
    {
        FrameGraph graph({.size = {1280, 720}});
        declareChain(graph, seen);
        graph.capture("blur.b");
        ASSERT_TRUE(graph.execute(pool, executor).ok());
        EXPECT_EQ(pool.inUseBytes(), kHdrBytes);
    }
    EXPECT_EQ(pool.inUseBytes(), 0u);
}

TEST(FrameGraphExecute, AZeroOutputSkipsTheFrame) {
    FakeAllocator gpu;
    TexturePool pool(gpu);
    RecordingExecutor executor;
    Seen seen;
    FrameGraph graph({.size = {0, 0}});
    declareChain(graph, seen);
    ASSERT_TRUE(graph.execute(pool, executor).ok());
    EXPECT_TRUE(executor.begun.empty());
    EXPECT_TRUE(gpu.created.empty());
    EXPECT_EQ(graph.report().findPass("scene")->status, PassStatus::FrameSkipped);
    EXPECT_EQ(graph.report().findPass("scene")->reason, "frame skipped: the output is 0x0");
}

TEST(FrameGraphExecute, ImportsAreNeitherAllocatedNorFreed) {
    FakeAllocator gpu;
    TexturePool pool(gpu);
    RecordingExecutor executor;
    FrameGraph graph({.size = {640, 480}, .native = 9});
    auto history = graph.importTexture("taa.history", {640, 480, TextureFormat::RGBA16F, 1}, 31);
    NativeTexture seenHistory = 0;
    NativeTexture seenOutput = 0;
    graph
        .addPass("resolve",
                 [&](PassContext& ctx) {
                     seenHistory = ctx.native(history);
                     seenOutput = ctx.native(ctx.graph().output());
                     EXPECT_EQ(ctx.targetSize(), (Size2D{640, 480}));
                 })
        .read(history)
        .writeColor(graph.output());
    ASSERT_TRUE(graph.execute(pool, executor).ok());
    EXPECT_EQ(seenHistory, 31u);
    EXPECT_EQ(seenOutput, 9u);
    EXPECT_TRUE(gpu.created.empty());
    EXPECT_TRUE(gpu.destroyed.empty());
    EXPECT_EQ(graph.report().findTexture("taa.history")->origin, TextureOrigin::Imported);
}

TEST(FrameGraphExecute, ABodyUsingAnUndeclaredTextureGetsNothingAndItIsLogged) {
    FakeAllocator gpu;
    TexturePool pool(gpu);
    RecordingExecutor executor;
    std::vector<std::string> logged;
    int sink = log::addSink([&](log::Level, std::string_view line) { logged.emplace_back(line); });
    FrameGraph graph({.size = {64, 64}});
    auto hidden = graph.declareTexture("hidden", kHdr);
    auto shown = graph.declareTexture("shown", kHdr);
    NativeTexture got = 123;
    graph.addPass("make").writeColor(hidden).writeColor(shown);
    graph.addPass("sneaky", [&](PassContext& ctx) { got = ctx.native(hidden); })
        .read(shown)
        .writeColor(graph.output());
    ASSERT_TRUE(graph.execute(pool, executor).ok());
    log::removeSink(sink);
    EXPECT_EQ(got, 0u);
    ASSERT_EQ(logged.size(), 1u);
    EXPECT_EQ(logged[0], "pass 'sneaky' used 'hidden' without declaring it");
}

TEST(FrameGraphExecute, ExecutesOncePerFrame) {
    FakeAllocator gpu;
    TexturePool pool(gpu);
    RecordingExecutor executor;
    FrameGraph graph({.size = {64, 64}});
    graph.addPass("present").writeColor(graph.output());
    EXPECT_TRUE(graph.execute(pool, executor).ok());
    EXPECT_FALSE(graph.execute(pool, executor).ok());
    EXPECT_EQ(executor.begun.size(), 1u);
}

TEST(FrameGraphExecute, PassCreateDeclaresAndWrites) {
    FakeAllocator gpu;
    TexturePool pool(gpu);
    RecordingExecutor executor;
    FrameGraph graph({.size = {1279, 719}});
    std::vector<TextureHandle> chain;
    Pass& down = graph.addPass("bloom down");
    for (int i = 1; i <= 3; ++i) {
        chain.push_back(down.create(cat("bloom.down[", i, "]"),
                                    {TextureSize::outputFraction(1, 1 << i), TextureFormat::R11F_G11F_B10F},
                                    TextureUsage::Storage));
    }
    graph.addPass("present").read(chain[0]).read(chain[1]).read(chain[2]).writeColor(graph.output());
    ASSERT_TRUE(graph.execute(pool, executor).ok()) << graph.errors().front();
    ASSERT_EQ(gpu.created.size(), 3u);
    EXPECT_EQ(gpu.created[2].label, "bloom.down[3]");
    EXPECT_EQ(gpu.created[2].spec, (TextureSpec{159, 89, TextureFormat::R11F_G11F_B10F, 1}));
    EXPECT_EQ(graph.targetSize(graph.pass(0)), (Size2D{639, 359}));
}

TEST(FrameGraphExecute, DescribesTheFrameAsText) {
    FakeAllocator gpu;
    TexturePool pool(gpu);
    RecordingExecutor executor;
    Seen seen;
    FrameGraph graph({.size = {1280, 720}});
    declareChain(graph, seen);
    ASSERT_TRUE(graph.execute(pool, executor).ok());
    std::string text = describe(graph.report());
    EXPECT_TRUE(test::contains(text, "ran     blur 3 (0.25 ms, fake clock)")) << text;
    EXPECT_TRUE(test::contains(text, "skipped debug: output unused")) << text;
    EXPECT_TRUE(
        test::contains(text,
                       "texture blur.c 1280x720 RGBA16F, 1 mip, 7372800 bytes, transient, from 'blur 3', "
                       "allocated"))
        << text;
}

}  // namespace
}  // namespace fx

namespace fx {
namespace {

TEST(FrameGraphExecute, AnExecutorCanRefuseAPass) {
    test::FakeAllocator gpu;
    TexturePool pool(gpu);
    test::RecordingExecutor executor;
    executor.refuse = {"broken"};
    FrameGraph graph({.size = {64, 64}});
    auto t = graph.declareTexture("t", {TextureSize::output(), TextureFormat::RGBA8});
    bool bodyRan = false;
    graph.addPass("broken", [&](PassContext&) { bodyRan = true; }).writeColor(t);
    graph.addPass("present").read(t).writeColor(graph.output());
    ASSERT_TRUE(graph.execute(pool, executor).ok());
    EXPECT_FALSE(bodyRan);
    EXPECT_EQ(executor.ended, (std::vector<std::string>{"broken", "present"}));  // endPass still runs
    const PassRecord* broken = graph.report().findPass("broken");
    EXPECT_FALSE(broken->executed);
    EXPECT_EQ(broken->status, PassStatus::ExecutorFailed);
    EXPECT_TRUE(graph.report().findPass("present")->executed);
    EXPECT_EQ(pool.inUseBytes(), 0u);  // its texture still goes back after the last reader
}

}  // namespace
}  // namespace fx
