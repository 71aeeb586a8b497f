// The feedback loop (Bloom chapter, hard case 12; Shader effects, hard case 14): sampling a texture
// attached to the framebuffer a pass draws into is undefined in GL. The graph refuses a pass that
// reads (samples) a texture it also writes as an attachment, naming both, unless the pass declares
// that it samples another mip level than it writes. Blending onto a texture (modify) is no loop.
#include <gtest/gtest.h>

#include "fake_gpu.hpp"
#include "render/frame_graph.hpp"

namespace fx {
namespace {

using test::contains;

const TextureDesc kHdr{TextureSize::output(), TextureFormat::RGBA16F};
const TextureDesc kDepth{TextureSize::output(), TextureFormat::Depth32F};

TEST(FeedbackLoop, SamplingTheColourTargetIsRefusedWithBothNames) {
    // Declared either way round: read then write, or write then read.
    for (bool readFirst : {true, false}) {
        FrameGraph graph({.size = {320, 180}});
        auto color = graph.declareTexture("scene.color", kHdr);
        graph.addPass("scene").writeColor(color);
        Pass& blur = graph.addPass("blur in place");
        if (readFirst) {
            blur.read(color).modify(color, TextureUsage::ColorAttachment);
        } else {
            blur.modify(color, TextureUsage::ColorAttachment).read(color);
        }
        graph.addPass("present").read(color).writeColor(graph.output());
        Status status = graph.compile();
        ASSERT_FALSE(status.ok()) << "read first: " << readFirst;
        ASSERT_EQ(graph.errors().size(), 1u) << status.error();
        EXPECT_EQ(
            graph.errors().front(),
            "pass 'blur in place' samples 'scene.color' and renders into it as its colour attachment: a "
            "feedback loop, undefined in GL. Render into another texture, or declare readOtherLevel if "
            "the pass samples another mip level than it writes");
    }
}

TEST(FeedbackLoop, SamplingTheTextureAPassCreatesIsRefused) {
    FrameGraph graph({.size = {320, 180}});
    auto level = graph.declareTexture("bloom.level", kHdr);
    graph.addPass("downsample").read(level).writeColor(level);
    graph.addPass("present").read(level).writeColor(graph.output());
    Status status = graph.compile();
    ASSERT_FALSE(status.ok());
    EXPECT_TRUE(contains(status.error(), "pass 'downsample' samples 'bloom.level' and renders into it"))
        << status.error();
}

TEST(FeedbackLoop, SamplingTheDepthTargetIsRefused) {
    FrameGraph graph({.size = {320, 180}});
    auto depth = graph.declareTexture("scene.depth", kDepth);
    auto color = graph.declareTexture("scene.color", kHdr);
    graph.addPass("prepass").writeDepth(depth);
    graph.addPass("soft particles")
        .read(depth)
        .modify(depth, TextureUsage::DepthAttachment)
        .writeColor(color);
    graph.addPass("present").read(color).writeColor(graph.output());
    Status status = graph.compile();
    ASSERT_FALSE(status.ok());
    EXPECT_TRUE(
        contains(status.error(),
                 "pass 'soft particles' samples 'scene.depth' and renders into it as its depth attachment"))
        << status.error();
}

TEST(FeedbackLoop, BlendingOntoATargetIsNoLoop) {
    // modify() reads through blending only: the bloom reference adds its levels this way.
    FrameGraph graph({.size = {320, 180}});
    auto sum = graph.declareTexture("bloom.sum", kHdr);
    auto level = graph.declareTexture("bloom.level", kHdr);
    graph.addPass("clear").writeColor(sum);
    graph.addPass("level").writeColor(level);
    graph.addPass("add").read(level).modify(sum, TextureUsage::ColorAttachment);
    graph.addPass("present").read(sum).writeColor(graph.output());
    EXPECT_TRUE(graph.compile().ok()) << graph.compile().error();
}

TEST(FeedbackLoop, AnotherMipLevelDeclaredIsAllowed) {
    // A mip chain in one texture: the pass samples level k and renders into level k+1.
    FrameGraph graph({.size = {320, 180}});
    auto chain = graph.declareTexture("bloom.chain", {TextureSize::output(), TextureFormat::RGBA16F, 4});
    graph.addPass("level 0").writeColor(chain);
    graph.addPass("level 1").readOtherLevel(chain).modify(chain, TextureUsage::ColorAttachment);
    graph.addPass("present").read(chain).writeColor(graph.output());
    Status status = graph.compile();
    EXPECT_TRUE(status.ok()) << status.error();
}

TEST(FeedbackLoop, StorageReadModifyWriteIsNoFramebufferLoop) {
    // A compute pass that samples a texture and writes it as an image has no framebuffer: not this rule.
    FrameGraph graph({.size = {320, 180}});
    auto field = graph.declareTexture("field", {TextureSize::output(), TextureFormat::RGBA32F});
    graph.addPass("seed").writeStorage(field);
    graph.addPass("relax").read(field).modify(field, TextureUsage::Storage);
    graph.addPass("present").read(field).writeColor(graph.output());
    Status status = graph.compile();
    EXPECT_TRUE(status.ok()) << status.error();
}

}  // namespace
}  // namespace fx
