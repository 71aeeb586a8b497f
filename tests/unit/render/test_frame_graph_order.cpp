#include <gtest/gtest.h>

#include "fake_gpu.hpp"
#include "render/frame_graph.hpp"

namespace fx {
namespace {

using test::names;
using Names = std::vector<std::string>;

const TextureDesc kHdr{TextureSize::output(), TextureFormat::RGBA16F};
const TextureDesc kShadow{TextureSize::absolute(2048, 2048), TextureFormat::Depth32F};

TEST(FrameGraphOrder, AReaderRunsAfterAWriterDeclaredLater) {
    FrameGraph graph({.size = {1280, 720}});
    auto shadowMap = graph.declareTexture("shadow.map", kShadow);
    auto color = graph.declareTexture("scene.color", kHdr);
    graph.addPass("scene").read(shadowMap).writeColor(color);
    graph.addPass("shadow map").writeDepth(shadowMap);
    graph.addPass("tonemap").read(color).writeColor(graph.output());
    ASSERT_TRUE(graph.compile().ok()) << graph.compile().error();
    EXPECT_EQ(names(graph, graph.derivedOrder()), (Names{"shadow map", "scene", "tonemap"}));
    EXPECT_EQ(names(graph, graph.executionOrder()), (Names{"shadow map", "scene", "tonemap"}));
    // Both orders are in the report for the overlay.
    EXPECT_EQ(graph.report().declaredOrder, (Names{"scene", "shadow map", "tonemap"}));
    EXPECT_EQ(graph.report().derivedOrder, (Names{"shadow map", "scene", "tonemap"}));
}

TEST(FrameGraphOrder, IndependentPassesKeepDeclarationOrder) {
    FrameGraph graph({.size = {640, 360}});
    auto a = graph.declareTexture("a", kHdr);
    auto b = graph.declareTexture("b", kHdr);
    auto c = graph.declareTexture("c", kHdr);
    graph.addPass("uses c").read(c).writeColor(a);
    graph.addPass("makes b").writeColor(b);
    graph.addPass("makes c").writeColor(c);
    graph.addPass("combine").read(a).read(b).writeColor(graph.output());
    ASSERT_TRUE(graph.compile().ok());
    // Only "uses c" moves, and only as far as it must.
    EXPECT_EQ(names(graph, graph.derivedOrder()), (Names{"makes b", "makes c", "uses c", "combine"}));
}

TEST(FrameGraphOrder, ModifiersFollowTheCreatorInDeclarationOrderAndPrecedeReaders) {
    FrameGraph graph({.size = {1280, 720}});
    auto sum = graph.declareTexture("bloom.sum", kHdr);
    auto level1 =
        graph.declareTexture("bloom.down[1]", {TextureSize::outputFraction(1, 2), TextureFormat::RGBA16F});
    auto level2 =
        graph.declareTexture("bloom.down[2]", {TextureSize::outputFraction(1, 4), TextureFormat::RGBA16F});
    graph.addPass("tonemap").read(sum).writeColor(graph.output());
    graph.addPass("add level 2").read(level2).modify(sum, TextureUsage::ColorAttachment);
    graph.addPass("add level 1").read(level1).modify(sum, TextureUsage::ColorAttachment);
    graph.addPass("downsample 2").read(level1).writeColor(level2);
    graph.addPass("copy scene").writeColor(sum);
    graph.addPass("downsample 1").writeColor(level1);
    ASSERT_TRUE(graph.compile().ok()) << graph.errors().front();
    EXPECT_EQ(names(graph, graph.derivedOrder()),
              (Names{"copy scene", "downsample 1", "downsample 2", "add level 2", "add level 1", "tonemap"}));
}

TEST(FrameGraphOrder, ReadAndWriteDeclaredSeparatelyIsAModify) {
    // A storage image: sampling a colour attachment of the same pass is a feedback loop the graph
    // refuses (test_feedback_loop.cpp).
    FrameGraph graph({.size = {64, 64}});
    auto acc = graph.declareTexture("accumulation", kHdr);
    graph.addPass("reader").read(acc).writeColor(graph.output());
    Pass& add = graph.addPass("add").writeStorage(acc).read(acc);
    graph.addPass("clear").writeStorage(acc);
    ASSERT_TRUE(graph.compile().ok());
    ASSERT_EQ(add.accesses().size(), 1u);
    EXPECT_TRUE(add.accesses()[0].modifies());
    EXPECT_EQ(names(graph, graph.derivedOrder()), (Names{"clear", "add", "reader"}));
}

TEST(FrameGraphOrder, StorageWritesOrderLikeAttachments) {
    FrameGraph graph({.size = {256, 256}});
    auto histogram = graph.declareTexture("luminance", {TextureSize::absolute(256, 1), TextureFormat::R32F});
    auto color = graph.declareTexture("scene.color", kHdr);
    graph.addPass("exposure").read(histogram).read(color).writeColor(graph.output());
    graph.addPass("histogram").read(color).writeStorage(histogram);
    graph.addPass("scene").writeColor(color);
    ASSERT_TRUE(graph.compile().ok());
    EXPECT_EQ(names(graph, graph.executionOrder()), (Names{"scene", "histogram", "exposure"}));
}

}  // namespace
}  // namespace fx

namespace fx {
namespace {

// The example in docs/frame-graph.md, so the document cannot drift from the code.
TEST(FrameGraphOrder, TheDocumentedExample) {
    for (bool hasEmitters : {true, false}) {
        FrameGraph graph({.size = {1280, 720}});
        auto shadowMap =
            graph.declareTexture("shadow.map", {TextureSize::absolute(2048, 2048), TextureFormat::Depth32F});
        auto sceneColor =
            graph.declareTexture("scene.color", {TextureSize::output(), TextureFormat::RGBA16F});
        auto sceneDepth =
            graph.declareTexture("scene.depth", {TextureSize::output(), TextureFormat::Depth24});
        graph.addPass("scene")
            .read(shadowMap)
            .writeColor(sceneColor)
            .writeDepth(sceneDepth)
            .setState({.depthTest = true,
                       .depthWrite = true,
                       .clearColor = ClearColor{0, 0, 0, 1},
                       .clearDepth = 1.0f});
        graph.addPass("shadow map")
            .writeDepth(shadowMap)
            .setState({.depthTest = true, .depthWrite = true, .clearDepth = 1.0f});
        auto& particles =
            graph.addPass("particles")
                .modify(sceneColor, TextureUsage::ColorAttachment)
                .read(sceneDepth)
                .setState({.depthWrite = false, .blend = true, .blendFunction = BlendFunction::additive()});
        if (!hasEmitters) particles.notCalledFor("scene has no particle emitter");
        graph.addPass("tonemap").read(sceneColor).writeColor(graph.output());
        ASSERT_TRUE(graph.compile().ok());
        if (hasEmitters) {
            EXPECT_EQ(test::names(graph, graph.executionOrder()),
                      (Names{"shadow map", "scene", "particles", "tonemap"}));
        } else {
            EXPECT_EQ(test::names(graph, graph.executionOrder()), (Names{"shadow map", "scene", "tonemap"}));
            EXPECT_EQ(graph.report().findPass("particles")->reason, "scene has no particle emitter");
        }
    }
}

}  // namespace
}  // namespace fx
