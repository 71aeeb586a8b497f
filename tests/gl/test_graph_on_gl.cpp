// The frame graph on GL: culling allocates nothing, inspecting brings a pass back, the state check
// names what a pass leaked, and every executed pass has a time.
#include "gl/readback.hpp"
#include "gl_test.hpp"
#include "render/frame_graph.hpp"
#include "render_gl/gl_pass_executor.hpp"
#include "render_gl/gl_state.hpp"
#include "render_gl/gl_texture_allocator.hpp"

using namespace fx;

namespace {

// Counts what the pool asks the GL allocator for.
class CountingAllocator final : public TextureAllocator {
public:
    NativeTexture create(const TextureSpec& spec, std::string_view label) override {
        created.emplace_back(label);
        return gl.create(spec, label);
    }
    void destroy(NativeTexture texture) override { gl.destroy(texture); }
    void relabel(NativeTexture texture, std::string_view label) override { gl.relabel(texture, label); }
    GlTextureAllocator gl;
    std::vector<std::string> created;
};

struct Harness {
    CountingAllocator allocator;
    TexturePool pool{allocator};
    PassTimer timer;
    GlPassExecutor executor;
    gl::Texture output = gl::Texture::create2D(TextureFormat::RGBA8, 16, 16, 1, "test.output");
    gl::Framebuffer outputFbo{"test.output"};

    explicit Harness(TimingMode mode = TimingMode::Fenced)
        : timer(mode, reinterpret_cast<const char*>(glGetString(GL_RENDERER))), executor(timer, {0, true}) {
        outputFbo.attachColor(0, output);
        outputFbo.setDrawBuffers(1);
        executor.setPresentFramebuffer(outputFbo.name());
    }
};

const TextureDesc kColor{TextureSize::output(), TextureFormat::RGBA16F, 1};

// A -> a, B -> b (nobody reads b), C reads a -> output.
void declareThreePasses(FrameGraph& graph, std::vector<std::string>& ran) {
    auto& a = graph.addPass("A", [&](PassContext&) { ran.push_back("A"); });
    TextureHandle texA = a.create("a", kColor, TextureUsage::ColorAttachment);
    a.setState({.clearColor = ClearColor{1, 0, 0, 1}});
    auto& b = graph.addPass("B", [&](PassContext&) { ran.push_back("B"); });
    b.create("b", kColor, TextureUsage::ColorAttachment);
    b.setState({.clearColor = ClearColor{0, 1, 0, 1}});
    graph.addPass("C", [&](PassContext&) { ran.push_back("C"); }).read(texA).writeColor(graph.output());
}

}  // namespace

class GraphOnGl : public GlTest {};

TEST_F(GraphOnGl, UnusedMiddlePassIsCulledAndAllocatesNothing) {
    Harness h;
    std::vector<std::string> ran;
    FrameGraph graph(OutputTarget{{16, 16}, "output", TextureFormat::RGBA8, 0});
    declareThreePasses(graph, ran);
    ASSERT_TRUE(graph.execute(h.pool, h.executor).ok());
    EXPECT_EQ(ran, (std::vector<std::string>{"A", "C"}));
    EXPECT_EQ(h.allocator.created, (std::vector<std::string>{"a"}));
    const PassRecord* b = graph.report().findPass("B");
    ASSERT_NE(b, nullptr);
    EXPECT_FALSE(b->executed);
    EXPECT_NE(b->reason.find("output unused"), std::string::npos) << b->reason;
    graph.releaseTextures();
}

TEST_F(GraphOnGl, InspectingTheUnusedTextureBringsItsPassBack) {
    Harness h;
    std::vector<std::string> ran;
    FrameGraph graph(OutputTarget{{16, 16}, "output", TextureFormat::RGBA8, 0});
    declareThreePasses(graph, ran);
    graph.inspect("b");
    ASSERT_TRUE(graph.execute(h.pool, h.executor).ok());
    EXPECT_EQ(ran, (std::vector<std::string>{"A", "B", "C"}));
    // The inspected texture is still held after execution, with what B cleared it to.
    const TextureView& b = graph.texture(*graph.findTexture("b"));
    ASSERT_NE(b.native, 0u);
    FloatImage pixels = gl::readTexture(b.native, b.spec);
    EXPECT_EQ(pixels.texel(3, 3, 1), 1.0f);
    EXPECT_EQ(pixels.texel(3, 3, 0), 0.0f);
    graph.releaseTextures();
}

TEST_F(GraphOnGl, StateCheckNamesWhatALeakyPassLeftBehind) {
    Harness h;
    restoreGlState(GlStateSnapshot::glInitial({16, 16}));
    FrameGraph graph(OutputTarget{{16, 16}, "output", TextureFormat::RGBA8, 0});
    // A pass that turns depth testing off in its body and does not say so: the chapter's shadow bug.
    graph.addPass("sort + ui", [](PassContext&) { glDisable(GL_DEPTH_TEST); })
        .writeColor(graph.output())
        .setState({.depthTest = true});
    graph.addPass("tidy", [](PassContext&) {})
        .modify(graph.output(), TextureUsage::ColorAttachment)
        .setState({.depthTest = true});
    ASSERT_TRUE(graph.execute(h.pool, h.executor).ok());
    const PassRecord* leaky = graph.report().findPass("sort + ui");
    ASSERT_NE(leaky, nullptr);
    ASSERT_EQ(leaky->stateLeft.size(), 1u);
    EXPECT_NE(leaky->stateLeft[0].find("depth test: off"), std::string::npos) << leaky->stateLeft[0];
    const PassRecord* tidy = graph.report().findPass("tidy");
    ASSERT_NE(tidy, nullptr);
    EXPECT_TRUE(tidy->stateLeft.empty());
    graph.releaseTextures();
}

TEST_F(GraphOnGl, EveryExecutedPassHasATimeWithEitherMethod) {
    for (TimingMode mode : {TimingMode::Fenced, TimingMode::Gpu}) {
        Harness h(mode);
        // GPU results arrive a few frames late: run several frames, then look.
        for (int frame = 0; frame < 8; ++frame) {
            std::vector<std::string> ran;
            FrameGraph graph(OutputTarget{{16, 16}, "output", TextureFormat::RGBA8, 0});
            declareThreePasses(graph, ran);
            ASSERT_TRUE(graph.execute(h.pool, h.executor).ok());
            graph.releaseTextures();
            h.pool.endFrame();
            glFinish();
            if (frame < 7) continue;
            for (const PassRecord& p : graph.report().passes) {
                if (!p.executed) continue;
                EXPECT_TRUE(p.timeMs.has_value()) << p.name << " with " << toString(h.timer.method());
                EXPECT_GE(p.timeMs.value_or(-1), 0.0);
                EXPECT_EQ(p.timingMethod, std::string(toString(h.timer.method())));
            }
        }
    }
}

TEST_F(GraphOnGl, SoftwareRendererIsTimedWithFences) {
    PassTimer timer(TimingMode::Automatic, "llvmpipe (LLVM 15.0.6, 256 bits)");
    EXPECT_EQ(timer.method(), TimingMethod::FencedWallClock);
    EXPECT_NE(timer.reason().find("software renderer"), std::string::npos);
    PassTimer hardware(TimingMode::Automatic, "NVIDIA H100 80GB HBM3/PCIe/SSE2");
    EXPECT_EQ(hardware.method(), TimingMethod::GpuTimestamps);
}
