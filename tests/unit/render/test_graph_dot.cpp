#include <gtest/gtest.h>

#include <string>

#include "fake_gpu.hpp"
#include "render/frame_graph.hpp"
#include "render/graph_dot.hpp"

namespace fx {
namespace {

const TextureDesc kHdr{TextureSize::output(), TextureFormat::RGBA16F};
const TextureDesc kShadow{TextureSize::absolute(1024, 1024), TextureFormat::Depth32F};

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// Lesson 03's shape in small: the scene pass is declared before the shadow pass whose map it reads,
// a debug view nobody looks at, particles for a scene without emitters, and one inspected texture.
struct SmallFrame {
    test::FakeAllocator allocator;
    TexturePool pool{allocator};
    test::RecordingExecutor executor;
    FrameGraph graph{{.size = {320, 180}}};
    std::string dot;

    SmallFrame() {
        auto map = graph.declareTexture("shadow.map", kShadow);
        auto color = graph.declareTexture("scene.color", kHdr);
        auto normals = graph.declareTexture("debug.normals", kHdr);
        auto mask = graph.declareTexture("mask \"quoted\"", kHdr);
        graph.addPass("scene").read(map).writeColor(color);
        graph.addPass("shadow map").writeDepth(map);
        graph.addPass("particles")
            .modify(color, TextureUsage::ColorAttachment)
            .notCalledFor("scene has no particle emitter");
        graph.addPass("debug normals").writeColor(normals);
        graph.addPass("mask").writeColor(mask);
        graph.addPass("present").read(color).writeColor(graph.output());
        graph.inspect("mask \"quoted\"");
        EXPECT_TRUE(graph.execute(pool, executor).ok());
        dot = toDot(graph.report());
    }
};

TEST(GraphDot, PassesAreBoxesNumberedInTheOrderTheyRan) {
    SmallFrame f;
    EXPECT_TRUE(f.dot.starts_with("digraph frame {\n")) << f.dot;
    EXPECT_TRUE(f.dot.ends_with("}\n"));
    // Declared second, ran first: the reordering the picture is for.
    EXPECT_TRUE(contains(f.dot, "[shape=box, label=\"1. shadow map\\n(declared 2nd)\"")) << f.dot;
    EXPECT_TRUE(contains(f.dot, "label=\"2. scene\\n(declared 1st)\"")) << f.dot;
    EXPECT_TRUE(contains(f.dot, "\"frame at 320x180\"")) << f.dot;
}

TEST(GraphDot, PassesThatDidNotRunAreGreyWithTheirReason) {
    SmallFrame f;
    // Long reasons are wrapped at spaces; the tooltip keeps the whole line.
    EXPECT_TRUE(contains(f.dot,
                         "label=\"particles\\nnot called for: scene has no\\nparticle emitter\", "
                         "style=\"rounded,filled,dashed\", fillcolor=\"#eeeeee\""))
        << f.dot;
    EXPECT_TRUE(contains(f.dot, "tooltip=\"not called for: scene has no particle emitter\"")) << f.dot;
    // The graph's own reason already begins with its status and is not repeated.
    EXPECT_TRUE(contains(f.dot, "label=\"debug normals\\noutput unused: 'debug.normals'\\nreaches")) << f.dot;
    EXPECT_FALSE(contains(f.dot, "output unused: output unused"));
}

TEST(GraphDot, TexturesAreEllipsesAndUnallocatedOnesAreGrey) {
    SmallFrame f;
    EXPECT_TRUE(contains(f.dot, "[shape=ellipse, label=\"shadow.map\\n1024x1024 Depth32F\", style=filled"))
        << f.dot;
    EXPECT_TRUE(contains(f.dot, "label=\"debug.normals\\n320x180 RGBA16F\\nnot allocated: output unused:"))
        << f.dot;
    EXPECT_TRUE(contains(f.dot, "label=\"output\\n320x180 RGBA8\\npresented output\"")) << f.dot;
}

TEST(GraphDot, EdgesFollowReadsAndWrites) {
    SmallFrame f;
    // Texture numbers follow declaration (the output is texture0); passes follow the report.
    const FrameReport& report = f.graph.report();
    auto passNode = [&](const std::string& name) {
        for (std::size_t p = 0; p < report.passes.size(); ++p) {
            if (report.passes[p].name == name) return "pass" + std::to_string(p);
        }
        return std::string("missing");
    };
    EXPECT_TRUE(contains(f.dot, passNode("shadow map") + " -> texture1;")) << f.dot;
    EXPECT_TRUE(contains(f.dot, "texture1 -> " + passNode("scene") + ";")) << f.dot;
    EXPECT_TRUE(contains(f.dot, passNode("present") + " -> texture0;")) << f.dot;
    // A modify from a pass that did not run: both ends, grey.
    EXPECT_TRUE(
        contains(f.dot, passNode("particles") +
                            " -> texture2 [dir=both, label=\"modify\", color=\"#9a9a9a\", style=dashed];"))
        << f.dot;
}

TEST(GraphDot, InspectedTexturesAreOutlinedTwiceAndNamesAreEscaped) {
    SmallFrame f;
    EXPECT_TRUE(contains(f.dot, "label=\"mask \\\"quoted\\\"\\n320x180 RGBA16F\\n[inspected]\"")) << f.dot;
    EXPECT_TRUE(contains(f.dot, "peripheries=2")) << f.dot;
}

// The state check's findings, as a GL executor records them (lesson 03, step 2).
TEST(GraphDot, APassThatInheritedStateIsOutlinedAndSaysWhat) {
    FrameReport report;
    report.outputSize = {320, 180};
    PassRecord shadow;
    shadow.name = "shadow map";
    shadow.stateInherited = {"depth test: off (inherited)"};
    PassRecord scene;
    scene.name = "scene";
    scene.declaredIndex = 1;
    scene.stateInherited = {"depth test: on (inherited)", "blend: on (inherited)",
                            "face culling: off (inherited)"};
    report.passes = {shadow, scene};
    std::string dot = toDot(report);
    EXPECT_TRUE(contains(dot,
                         "label=\"1. shadow map\\n(declared 1st)\\ninherits depth test: off\", "
                         "style=\"rounded,filled\", fillcolor=\"#dbe8f6\", color=\"#c0392b\", penwidth=2, "
                         "tooltip=\"inherits:\\ndepth test: off\"];"))
        << dot;
    // Three or more are counted in the label and listed in the tooltip.
    EXPECT_TRUE(contains(dot, "label=\"2. scene\\n(declared 2nd)\\ninherits 3 settings\"")) << dot;
    EXPECT_TRUE(contains(dot, "tooltip=\"inherits:\\ndepth test: on\\nblend: on\\nface culling: off\""))
        << dot;
}

TEST(GraphDot, AFrameWithErrorsSaysNothingRan) {
    test::FakeAllocator allocator;
    TexturePool pool(allocator);
    test::RecordingExecutor executor;
    FrameGraph graph({.size = {8, 8}});
    auto never = graph.declareTexture("never.written", kHdr);
    graph.addPass("reader").read(never).writeColor(graph.output());
    EXPECT_FALSE(graph.execute(pool, executor).ok());
    EXPECT_TRUE(contains(toDot(graph.report()), "\"frame at 8x8, 1 error(s): nothing ran\""));
}

TEST(GraphDot, TheSameGraphTopToBottom) {
    FrameReport report;
    report.outputSize = {8, 8};
    const std::string leftToRight = toDot(report);
    const std::string topDown = topToBottom(leftToRight);
    EXPECT_TRUE(contains(leftToRight, "rankdir=LR"));
    EXPECT_TRUE(contains(topDown, "graph [rankdir=TB, bgcolor=\"white\""));
    EXPECT_FALSE(contains(topDown, "rankdir=LR"));
    EXPECT_EQ(topDown.size(), leftToRight.size());  // nothing else changed
}

}  // namespace
}  // namespace fx
