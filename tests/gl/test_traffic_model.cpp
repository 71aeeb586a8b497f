// The traffic model on the effects' own declarations (render/pass_traffic.hpp): the bloom chain of
// lessons 06 and 07, the depth-of-field gather of lesson 09 and the G-buffer layouts of lesson 10,
// declared on a 1920x1080 frame graph (compiled, not run) and compared with hand counts in bytes. The
// model's rules themselves, and the reference note's two bloom figures, are tests/unit/render/
// test_pass_traffic.cpp.
#include "effects/bloom/bloom_chain.hpp"
#include "effects/bloom/bloom_composite.hpp"
#include "effects/deferred/gbuffer_pass.hpp"
#include "effects/dof/depth_of_field.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "gl_test.hpp"
#include "scene/scene.hpp"

using namespace fx;

namespace {

constexpr std::uint64_t kPixels = 1920u * 1080u;

std::uint64_t trafficOf(const FrameReport& report, const std::string& name) {
    const PassRecord* p = report.findPass(name);
    EXPECT_NE(p, nullptr) << name;
    EXPECT_TRUE(p && p->taps) << name << " declares no taps";
    return p ? p->traffic.total() : 0;
}

class TrafficModelOnGl : public GlTest {};

TEST_F(TrafficModelOnGl, TheBloomChainMovesFortyMegabytesAtTenEightyP) {
    BloomChain chain;
    BloomComposite composite;
    ASSERT_TRUE(programsBuilt());
    FrameGraph graph({.size = {1920, 1080}});
    Pass& scene = graph.addPass("scene").setTaps(2);
    TextureHandle hdr = scene.create("scene.color", {TextureSize::output(), TextureFormat::RGBA16F},
                                     TextureUsage::ColorAttachment);
    BloomChainSettings settings = bloomChapterChain(1.0f, 6);
    BloomChain::Declared d = chain.declare(graph, hdr, settings);
    ASSERT_EQ(d.levels.size(), 6u);
    DeclaredPass glow = composite.declare(graph, hdr, d.glow(), {BloomFilters::bloomChapter, 0.5f, 1.0f});
    graph.addPass("present").read(glow.output).writeColor(graph.output()).setTaps(1);
    ASSERT_TRUE(graph.compile());

    // Levels 960x540 down to 30x16 at 8 bytes (RGBA16F); the bright pass reads the 16.6 MB scene.
    const std::uint64_t L[6] = {4147200, 1036800, 259200, 64320, 15840, 3840};
    const std::uint64_t scene16 = kPixels * 8;
    std::uint64_t chainBytes = 0;
    for (const Pass* p : d.passes) chainBytes += trafficOf(graph.report(), p->name());
    EXPECT_EQ(trafficOf(graph.report(), "bloom bright pass"), scene16 + L[0]);
    EXPECT_EQ(trafficOf(graph.report(), "bloom down 1"), L[0] + L[1]);
    EXPECT_EQ(trafficOf(graph.report(), "bloom up 4"), L[4] + L[5] + L[4]);
    EXPECT_EQ(trafficOf(graph.report(), "bloom up 0"), L[0] + L[1] + L[0]);
    EXPECT_EQ(chainBytes, 40066080u);  // 40.1 MB, the published mip-chain bloom's "about 40 MB"
    // The composite reads the scene and the glow and writes bloom.result, all RGBA16F.
    EXPECT_EQ(trafficOf(graph.report(), "bloom composite"), scene16 + L[0] + scene16);
}

TEST_F(TrafficModelOnGl, TheDepthOfFieldGatherAtHalfResolution) {
    DepthOfField dof;
    ASSERT_TRUE(programsBuilt());
    FrameGraph graph({.size = {1920, 1080}});
    Pass& scene = graph.addPass("scene").setTaps(2);
    TextureHandle color = scene.create("scene.color", {TextureSize::output(), TextureFormat::RGBA16F},
                                       TextureUsage::ColorAttachment);
    TextureHandle depth = scene.create("scene.depth", {TextureSize::output(), TextureFormat::Depth32F},
                                       TextureUsage::DepthAttachment);
    DofLensUniforms lens{1.0f / 3.0f, 500.0f, 32.0f, 0.5f, 0.1f, 100.0f};
    DeclaredPass coc = dof.declareCoc(graph, depth, lens);
    DepthOfField::Gather g = dof.declareGather(graph, color, coc.output, lens, {22, true, true, 0.0f});
    graph.addPass("present").read(g.result).writeColor(graph.output()).setTaps(1);
    ASSERT_TRUE(graph.compile());

    const std::uint64_t full4 = kPixels * 4, full8 = kPixels * 8;  // D32F or R32F; RGBA16F
    const std::uint64_t half8 = 960u * 540u * 8u;                  // the gather's RGBA16F
    const std::uint64_t tiles = 120u * 67u * 4u;                   // RG16F, one texel per 16x16 pixels
    EXPECT_EQ(trafficOf(graph.report(), "dof coc"), full4 + full4);
    EXPECT_EQ(trafficOf(graph.report(), "dof prefilter"), full8 + full4 + half8);
    EXPECT_EQ(trafficOf(graph.report(), "dof tile max"), half8 + tiles);
    EXPECT_EQ(trafficOf(graph.report(), "dof gather"), half8 + tiles + half8);
    EXPECT_EQ(trafficOf(graph.report(), "dof composite"), full8 + full4 + half8 + full8);
    // 103.7 MB in all: the reference note's Unity-style 89 MB stores the CoC in R8, here it is R32F.
    std::uint64_t total = 0;
    for (const char* name : {"dof coc", "dof prefilter", "dof tile max", "dof gather", "dof composite"})
        total += trafficOf(graph.report(), name);
    EXPECT_EQ(total, 103744320u);
    // The gather's taps: its centre, the tiles within the clamp's reach and the 22-tap kernel. A 32-pixel
    // CoC diameter is a 8-texel radius at half resolution: one tile of 8 texels each way.
    const PassRecord* gather = graph.report().findPass("dof gather");
    ASSERT_TRUE(gather && gather->taps);
    EXPECT_EQ(*gather->taps, 1 + 9 + 22);
}

TEST_F(TrafficModelOnGl, TheGBufferLayoutsWriteTwelveTwentyFourAndFortyBytesAPixel) {
    GBufferPass gbuffer;
    Scene scene;
    SceneMeshes meshes(scene);
    for (auto [layout, bytes] :
         {std::pair{GBufferLayout::compact, 12u}, {GBufferLayout::fat, 24u}, {GBufferLayout::fat32, 40u}}) {
        FrameGraph graph({.size = {1920, 1080}});
        GBufferTargets g = gbuffer.declare(graph, World(scene, meshes, 0.0), {layout});
        Pass& read = graph.addPass("read").read(g.albedo).read(g.normal).read(g.depth).setTaps(3);
        if (g.position) read.read(*g.position);
        read.writeColor(graph.output());
        ASSERT_TRUE(graph.compile());
        EXPECT_EQ(bytes, unsigned(gbufferBytesPerPixel(layout)));
        const PassRecord* p = graph.report().findPass("gbuffer");
        ASSERT_NE(p, nullptr);
        EXPECT_EQ(p->traffic.writtenBytes, kPixels * bytes) << toString(layout);
        EXPECT_EQ(p->traffic.readBytes, 0u) << toString(layout);  // material textures are not in the graph
        // Whoever reads the whole G-buffer back reads the same bytes.
        EXPECT_EQ(graph.report().findPass("read")->traffic.readBytes, kPixels * bytes) << toString(layout);
    }
}

}  // namespace
