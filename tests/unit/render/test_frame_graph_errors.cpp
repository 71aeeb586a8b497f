#include <gtest/gtest.h>

#include "fake_gpu.hpp"
#include "render/frame_graph.hpp"

namespace fx {
namespace {

using test::contains;

const TextureDesc kHdr{TextureSize::output(), TextureFormat::RGBA16F};

// The one error a graph reports, or a failure naming all of them.
std::string onlyError(FrameGraph& graph) {
    Status status = graph.compile();
    EXPECT_FALSE(status.ok());
    EXPECT_EQ(graph.errors().size(), 1u) << status.error();
    return graph.errors().empty() ? std::string() : graph.errors().front();
}

TEST(FrameGraphErrors, ReadingSomethingNobodyWrites) {
    FrameGraph graph({.size = {1280, 720}});
    auto color = graph.declareTexture("scene.color", kHdr);
    graph.addPass("tonemap").read(color).writeColor(graph.output());
    EXPECT_EQ(onlyError(graph),
              "'tonemap' reads 'scene.color', which no pass writes and which is not imported");
}

TEST(FrameGraphErrors, ModifyingSomethingNobodyCreates) {
    FrameGraph graph({.size = {1280, 720}});
    auto sum = graph.declareTexture("bloom.sum", kHdr);
    graph.addPass("add 1").modify(sum, TextureUsage::ColorAttachment);
    graph.addPass("add 2").modify(sum, TextureUsage::ColorAttachment);
    graph.addPass("present").read(sum).writeColor(graph.output());
    EXPECT_EQ(onlyError(graph),
              "'add 1' and 'add 2' modify 'bloom.sum', but no pass creates it (writes it without reading it) "
              "and it is not imported");
}

TEST(FrameGraphErrors, ReadingAnImportNobodyWritesIsFine) {
    FrameGraph graph({.size = {1280, 720}});
    auto lut = graph.importTexture("cloud.noise", {128, 128, TextureFormat::R8, 1}, 5);
    graph.addPass("clouds").read(lut).writeColor(graph.output());
    EXPECT_TRUE(graph.compile().ok());
}

TEST(FrameGraphErrors, TwoCreatorsWithoutAnOrder) {
    FrameGraph graph({.size = {1280, 720}});
    auto color = graph.declareTexture("scene.color", kHdr);
    graph.addPass("sky").writeColor(color);
    graph.addPass("scene").writeColor(color);
    graph.addPass("present").read(color).writeColor(graph.output());
    std::string error = onlyError(graph);
    EXPECT_TRUE(contains(error, "'scene.color' is written without being read by 'sky' and 'scene'")) << error;
    EXPECT_TRUE(contains(error, "only one pass may create a texture")) << error;
}

TEST(FrameGraphErrors, CycleNamesItsPassesAndTextures) {
    FrameGraph graph({.size = {1280, 720}});
    auto x = graph.declareTexture("x", kHdr);
    auto y = graph.declareTexture("y", kHdr);
    graph.addPass("present").read(y).writeColor(graph.output());
    graph.addPass("a").read(y).writeColor(x);
    graph.addPass("b").read(x).writeColor(y);
    EXPECT_EQ(onlyError(graph),
              "passes form a cycle: 'a' -> 'b' -> 'a' ('b' reads 'x' written by 'a'; 'a' reads 'y' written "
              "by 'b')");
    EXPECT_TRUE(graph.report().derivedOrder.empty());
}

TEST(FrameGraphErrors, CycleThroughModifiersDeclaredInTheWrongOrder) {
    FrameGraph graph({.size = {1280, 720}});
    auto acc = graph.declareTexture("acc", kHdr);
    auto mask = graph.declareTexture("mask", kHdr);
    graph.addPass("clear").writeColor(acc);
    graph.addPass("first add").read(mask).modify(acc, TextureUsage::ColorAttachment);
    graph.addPass("second add").modify(acc, TextureUsage::ColorAttachment).writeStorage(mask);
    std::string error = onlyError(graph);
    EXPECT_EQ(
        error,
        "passes form a cycle: 'first add' -> 'second add' -> 'first add' ('second add' modifies 'acc' after "
        "'first add' (modifiers follow declaration order); 'first add' reads 'mask' written by 'second "
        "add')");
}

TEST(FrameGraphErrors, FormatsAPassCannotRenderTo) {
    FrameGraph graph({.size = {1280, 720}});
    auto depth = graph.declareTexture("scene.depth", {TextureSize::output(), TextureFormat::Depth32F});
    auto rgb = graph.declareTexture("positions", {TextureSize::output(), TextureFormat::RGB32F});
    auto hdr = graph.declareTexture("scene.color", kHdr);
    auto srgb = graph.declareTexture("ldr", {TextureSize::output(), TextureFormat::SRGB8_ALPHA8});
    graph.addPass("wrong colour").writeColor(depth);
    graph.addPass("gbuffer").writeColor(rgb);
    graph.addPass("wrong depth").writeDepth(hdr);
    graph.addPass("compute").writeStorage(srgb);
    ASSERT_FALSE(graph.compile().ok());
    EXPECT_EQ(
        graph.errors(),
        (std::vector<std::string>{
            "pass 'wrong colour' writes 'scene.depth' as a colour attachment, but its format Depth32F is "
            "not colour-renderable",
            "pass 'gbuffer' writes 'positions' as a colour attachment, but its format RGB32F is not "
            "colour-renderable",
            "pass 'wrong depth' writes 'scene.color' as a depth attachment, but its format RGBA16F is not a "
            "depth format",
            "pass 'compute' writes 'ldr' as a storage image, but its format SRGB8_ALPHA8 cannot be used for "
            "image load/store",
        }));
}

TEST(FrameGraphErrors, ATextureThatResolvesToZero) {
    FrameGraph graph({.size = {1280, 720}});
    auto empty = graph.declareTexture("lut", {TextureSize::absolute(0, 16), TextureFormat::R8});
    graph.addPass("bake").writeColor(empty);
    EXPECT_EQ(onlyError(graph),
              "texture 'lut' (0x16) resolves to 0x16 at output 1280x720; a texture needs at least 1x1");

    FrameGraph zeroFraction({.size = {1280, 720}});
    zeroFraction.declareTexture("none", {TextureSize::outputFraction(0, 4), TextureFormat::R8});
    EXPECT_EQ(onlyError(zeroFraction),
              "texture 'none' (0/4 output) resolves to 0x0 at output 1280x720; a texture needs at least 1x1");

    FrameGraph badFraction({.size = {1280, 720}});
    badFraction.declareTexture("bad", {TextureSize::outputFraction(1, 0), TextureFormat::R8});
    EXPECT_EQ(onlyError(badFraction),
              "texture 'bad' is sized 1/0 of the output; the denominator must be positive");
}

TEST(FrameGraphErrors, AZeroOutputStillCompiles) {
    FrameGraph graph({.size = {0, 0}});
    auto quarter = graph.declareTexture(
        "bloom.down[2]", {TextureSize::outputFraction(1, 4), TextureFormat::RGBA16F, kFullMipChain});
    auto shadow =
        graph.declareTexture("shadow.map", {TextureSize::absolute(1024, 1024), TextureFormat::Depth32F});
    graph.addPass("shadow").writeDepth(shadow);
    graph.addPass("bloom").read(shadow).writeColor(quarter);
    graph.addPass("present").read(quarter).writeColor(graph.output());
    ASSERT_TRUE(graph.compile().ok()) << graph.errors().front();
    EXPECT_EQ(graph.texture(quarter).spec, (TextureSpec{0, 0, TextureFormat::RGBA16F, 1}));
    EXPECT_EQ(graph.executionOrder().size(), 3u);
}

TEST(FrameGraphErrors, DeclarationMistakes) {
    FrameGraph other({.size = {8, 8}});
    for (int i = 0; i < 3; ++i) other.declareTexture("t" + std::to_string(i), kHdr);
    TextureHandle foreign = other.declareTexture("foreign", kHdr);

    FrameGraph graph({.size = {8, 8}});
    auto t = graph.declareTexture("t", {TextureSize::output(), TextureFormat::Depth24Stencil8});
    graph.declareTexture("t", kHdr);
    graph.addPass("p").read(foreign);
    graph.addPass("p").writeDepth(t).write(t, TextureUsage::Storage);
    graph.addPass("q").read(TextureHandle{});
    ASSERT_FALSE(graph.compile().ok());
    EXPECT_EQ(graph.errors(), (std::vector<std::string>{
                                  "two textures are named 't'",
                                  "two passes are named 'p'",
                                  "pass 'p' uses a texture handle this frame's graph did not declare",
                                  "pass 'p' writes 't' both as depth attachment and as storage image",
                                  "pass 'q' uses a texture handle this frame's graph did not declare",
                              }));
}

TEST(FrameGraphErrors, AttachmentsThatCannotShareAFramebuffer) {
    FrameGraph graph({.size = {1280, 720}});
    auto color = graph.declareTexture("scene.color", kHdr);
    auto half = graph.declareTexture("half", {TextureSize::outputFraction(1, 2), TextureFormat::RGBA16F});
    auto d1 = graph.declareTexture("d1", {TextureSize::output(), TextureFormat::Depth24});
    auto d2 = graph.declareTexture("d2", {TextureSize::output(), TextureFormat::Depth32F});
    graph.addPass("mismatch").writeColor(color).writeColor(half);
    graph.addPass("two depths").writeDepth(d1).writeDepth(d2);
    graph.addPass("window and texture").writeColor(graph.output()).writeDepth(d1);
    graph.addPass("sample window").read(graph.output()).writeColor(color);
    ASSERT_FALSE(graph.compile().ok());
    const auto& e = graph.errors();
    ASSERT_GE(e.size(), 4u);
    EXPECT_EQ(e[0],
              "pass 'mismatch' draws into 'scene.color' (1280x720) and 'half' (640x360); the attachments of "
              "one pass "
              "must have one size");
    EXPECT_EQ(e[1], "pass 'two depths' has 2 depth attachments ('d1', 'd2'); a framebuffer has one");
    EXPECT_EQ(
        e[2],
        "pass 'window and texture' draws into 'output', the window's framebuffer, and also into 'd1'; the "
        "window's framebuffer cannot share a pass with texture attachments");
    EXPECT_EQ(e[3],
              "pass 'sample window' samples 'output', the window's framebuffer, which cannot be read as a "
              "texture");
}

TEST(FrameGraphErrors, AHeadlessOutputTextureCanBeSampledAndCombined) {
    FrameGraph graph({.size = {64, 64}, .native = 42});
    auto depth = graph.declareTexture("depth", {TextureSize::output(), TextureFormat::Depth24});
    graph.addPass("draw").writeColor(graph.output()).writeDepth(depth);
    graph.addPass("fxaa").read(graph.output()).writeColor(graph.declareTexture("aa", kHdr));
    EXPECT_TRUE(graph.compile().ok());
}

TEST(FrameGraphErrors, AllErrorsAreReportedAtOnceAndNothingRuns) {
    FrameGraph graph({.size = {1280, 720}});
    auto color = graph.declareTexture("scene.color", kHdr);
    auto positions = graph.declareTexture("positions", {TextureSize::output(), TextureFormat::RGB32F});
    bool ran = false;
    graph.addPass("gbuffer", [&](PassContext&) { ran = true; }).writeColor(positions);
    graph.addPass("clear", [&](PassContext&) { ran = true; }).writeColor(graph.output());
    graph.addPass("tonemap", [&](PassContext&) { ran = true; }).read(color).writeColor(graph.output());
    Status status = graph.compile();
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(graph.errors().size(), 3u);  // format, creators of output, unwritten read
    EXPECT_TRUE(contains(status.error(), "RGB32F")) << status.error();
    EXPECT_TRUE(contains(status.error(), "'scene.color'")) << status.error();

    test::FakeAllocator gpu;
    TexturePool pool(gpu);
    test::RecordingExecutor executor;
    EXPECT_FALSE(graph.execute(pool, executor).ok());
    EXPECT_FALSE(ran);
    EXPECT_EQ(graph.report().findPass("tonemap")->reason, "frame skipped: the frame graph has errors");
    EXPECT_TRUE(executor.begun.empty());
    EXPECT_TRUE(gpu.created.empty());
}

}  // namespace
}  // namespace fx
