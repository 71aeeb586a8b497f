// The traffic model (render/pass_traffic.hpp) against hand counts: every texture a pass samples read
// once at 1920x1080's size and its format, every texture it writes written once, one it adds into read
// and written; the frame's totals over the passes that run; taps weighted by the pixels a pass writes.
// The bloom chain and the full-resolution Gaussians are the reference note's two figures (about 40 MB
// and 332 MB a frame at 1080p). The effects' own declarations are checked against the same counts on
// GL (tests/gl/test_traffic_model.cpp).
#include <gtest/gtest.h>

#include "base/log.hpp"
#include "render/frame_graph.hpp"

namespace fx {
namespace {

// 1920 x 1080 pixels, and one full-size texture of each size used here, in bytes.
constexpr std::uint64_t kPixels = 1920u * 1080u;
constexpr std::uint64_t kRgba16f = kPixels * 8u;  // 16.6 MB
constexpr std::uint64_t kRgba8 = kPixels * 4u;    // 8.3 MB

const TextureDesc kHdr{TextureSize::output(), TextureFormat::RGBA16F};

const PassRecord& pass(const FrameGraph& graph, const std::string& name) {
    const PassRecord* p = graph.report().findPass(name);
    EXPECT_NE(p, nullptr) << name;
    static const PassRecord none;
    return p ? *p : none;
}

TEST(PassTraffic, ReadsOnceWritesOnceAndAddingIntoIsBoth) {
    // The frame's own size does not matter: the model takes every output-relative texture at 1080p.
    FrameGraph graph({.size = {320, 180}});
    auto scene = graph.declareTexture("scene", kHdr);
    auto half = graph.declareTexture("half", {TextureSize::outputFraction(1, 2), TextureFormat::RGBA16F});
    auto sum = graph.declareTexture("sum", kHdr);
    graph.addPass("scene").writeColor(scene).setTaps(2);
    graph.addPass("down").read(scene).writeColor(half).setTaps(13);
    graph.addPass("clear").writeColor(sum).setTaps(0);
    graph.addPass("add").read(half).modify(sum, TextureUsage::ColorAttachment).setTaps(9);
    graph.addPass("present").read(sum).writeColor(graph.output()).setTaps(1);
    ASSERT_TRUE(graph.compile());

    const std::uint64_t halfBytes = 960u * 540u * 8u;
    EXPECT_EQ(pass(graph, "scene").traffic.readBytes, 0u);
    EXPECT_EQ(pass(graph, "scene").traffic.writtenBytes, kRgba16f);
    EXPECT_EQ(pass(graph, "down").traffic.readBytes, kRgba16f);  // 13 taps, one read
    EXPECT_EQ(pass(graph, "down").traffic.writtenBytes, halfBytes);
    EXPECT_EQ(pass(graph, "add").traffic.readBytes, halfBytes + kRgba16f);  // what it adds into, read too
    EXPECT_EQ(pass(graph, "add").traffic.writtenBytes, kRgba16f);
    // The presented output is RGBA8 (the OutputTarget's default) at 1080p.
    EXPECT_EQ(pass(graph, "present").traffic.writtenBytes, kRgba8);

    const PassTraffic total = graph.report().modelledTraffic();
    EXPECT_EQ(total.readBytes, 3 * kRgba16f + halfBytes);
    EXPECT_EQ(total.writtenBytes, 3 * kRgba16f + halfBytes + kRgba8);
    // Taps per output pixel: 2 + 13/4 + 0 + 9 + 1 (the downsample writes a quarter of the pixels).
    EXPECT_DOUBLE_EQ(graph.report().tapsPerOutputPixel(), 2.0 + 13.0 / 4.0 + 9.0 + 1.0);
    EXPECT_TRUE(graph.report().undeclaredTaps().empty());
}

TEST(PassTraffic, ImportsKeepTheirSizeUnlessTheyFollowTheOutput) {
    FrameGraph graph({.size = {640, 360}});
    const TextureSpec history{320, 180, TextureFormat::RGBA16F, 1};
    auto fixed = graph.importTexture("fixed", {512, 512, TextureFormat::RGBA8, 1}, 1);
    auto previous = graph.importTexture("history", history, 2, TextureSize::outputFraction(1, 2));
    graph.addPass("use").read(fixed).read(previous).writeColor(graph.output()).setTaps(2);
    ASSERT_TRUE(graph.compile());
    EXPECT_EQ(pass(graph, "use").traffic.readBytes, 512u * 512u * 4u + 960u * 540u * 8u);
}

TEST(PassTraffic, PassesThatDoNotRunCostNothingAndUndeclaredTapsAreListed) {
    FrameGraph graph({.size = {1920, 1080}});
    auto scene = graph.declareTexture("scene", kHdr);
    auto unused = graph.declareTexture("unused", kHdr);
    graph.addPass("scene").writeColor(scene);  // no taps declared
    graph.addPass("culled").read(scene).writeColor(unused).setTaps(5);
    graph.addPass("off").read(scene).modify(graph.output(), TextureUsage::ColorAttachment).disable("step 1");
    graph.addPass("present").read(scene).writeColor(graph.output()).setTaps(1);
    ASSERT_TRUE(graph.compile());
    EXPECT_EQ(graph.report().modelledTraffic().total(), kRgba16f + kRgba16f + kRgba8);
    EXPECT_EQ(graph.report().undeclaredTaps(), std::vector<std::string>{"scene"});
    EXPECT_DOUBLE_EQ(graph.report().tapsPerOutputPixel(), 1.0);
}

// The lesson 06 chain's shape (BloomChain: every level its own texture): the bright pass from the
// RGBA16F scene into level 0 at half size, five downsamples, and five upsamples each reading its own
// level and the sum below it into a texture of its own. Six levels from 960x540 to 30x16.
TEST(PassTraffic, TheBloomChainIsAboutFortyMegabytesAtTenEightyP) {
    FrameGraph graph({.size = {1920, 1080}});
    auto scene = graph.declareTexture("scene", kHdr);
    graph.addPass("scene").writeColor(scene).setTaps(2);
    // Level k is the output divided by 2^(k+1) (effects/bloom/bloom_levels.hpp, first divisor 2).
    constexpr std::size_t kLevels = 6;
    std::vector<TextureHandle> down, up(kLevels);
    auto level = [&](const char* chain, std::size_t k) {
        return graph.declareTexture(cat(chain, k),
                                    {TextureSize::outputFraction(1, int(2u << k)), TextureFormat::RGBA16F});
    };
    down.push_back(level("down", 0));
    graph.addPass("bright").read(scene).writeColor(down[0]).setTaps(4);
    for (std::size_t k = 1; k < kLevels; ++k) {
        down.push_back(level("down", k));
        graph.addPass(cat("down ", k)).read(down[k - 1]).writeColor(down[k]).setTaps(4);
    }
    for (std::size_t k = kLevels - 1; k-- > 0;) {
        up[k] = level("up", k);
        TextureHandle below = k + 2 < kLevels ? up[k + 1] : down[k + 1];
        graph.addPass(cat("up ", k)).read(down[k]).read(below).writeColor(up[k]).setTaps(9);
    }
    graph.addPass("composite").read(scene).read(up[0]).writeColor(graph.output()).setTaps(2);
    ASSERT_TRUE(graph.compile());

    // By hand, in bytes: the levels 960x540, 480x270, 240x135, 120x67, 60x33 and 30x16 at 8 bytes.
    const std::uint64_t L[6] = {4147200, 1036800, 259200, 64320, 15840, 3840};
    const std::uint64_t bright = kRgba16f + L[0];
    const std::uint64_t downs = (L[0] + L[1] + L[2] + L[3] + L[4]) + (L[1] + L[2] + L[3] + L[4] + L[5]);
    // Up k reads level k and level k+1 (the sum below), writes level k's size.
    const std::uint64_t ups = (L[0] + L[1] + L[2] + L[3] + L[4]) + (L[1] + L[2] + L[3] + L[4] + L[5]) +
                              (L[0] + L[1] + L[2] + L[3] + L[4]);
    std::uint64_t chain = 0;
    for (const PassRecord& p : graph.report().passes) {
        if (p.name != "scene" && p.name != "composite") chain += p.traffic.total();
    }
    EXPECT_EQ(chain, bright + downs + ups);
    EXPECT_EQ(chain, 40066080u);  // 40.1 MB: the published mip-chain bloom's "about 40 MB"
    EXPECT_EQ(pass(graph, "composite").traffic.total(), kRgba16f + L[0] + kRgba8);
}

// The classic teaching bloom: ten separable 9-tap Gaussian passes at full resolution, ping-ponging
// between two RGBA16F targets: the reference note's 332 MB (each pass reads and writes 16.6 MB).
TEST(PassTraffic, TenFullResolutionGaussiansAreAboutThreeHundredThirtyMegabytes) {
    FrameGraph graph({.size = {1920, 1080}});
    TextureHandle current = graph.declareTexture("bright", kHdr);
    graph.addPass("bright").writeColor(current).setTaps(1);
    std::uint64_t blur = 0;
    for (int i = 0; i < 10; ++i) {
        TextureHandle next = graph.declareTexture(cat("blur", i), kHdr);
        graph.addPass(cat("gaussian ", i)).read(current).writeColor(next).setTaps(9);
        current = next;
    }
    graph.addPass("present").read(current).writeColor(graph.output()).setTaps(1);
    ASSERT_TRUE(graph.compile());
    for (int i = 0; i < 10; ++i) blur += pass(graph, cat("gaussian ", i)).traffic.total();
    EXPECT_EQ(blur, 331776000u);  // 331.8 MB
    // 90 taps per pixel, as the note counts them.
    EXPECT_DOUBLE_EQ(graph.report().tapsPerOutputPixel(), 1.0 + 90.0 + 1.0);
}

TEST(PassTraffic, MegabytesAreDecimal) {
    EXPECT_EQ(megabytesText(40066080u), "40.1 MB");
    EXPECT_EQ(megabytesText(0), "0.0 MB");
}

}  // namespace
}  // namespace fx
