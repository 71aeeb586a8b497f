// Pass groups: a handle for "the bloom chain" that answers what its passes cost and which textures
// they made from a frame report, without matching pass names; and requirements (Pass::needs) that the
// graph turns into "not called for" with the reason it was given.
#include <gtest/gtest.h>

#include "fake_gpu.hpp"
#include "render/frame_graph.hpp"

namespace fx {
namespace {

using test::FakeAllocator;
using test::RecordingExecutor;
using Names = std::vector<std::string>;

const TextureDesc kHdr{TextureSize::output(), TextureFormat::RGBA16F};

struct GlowFrame {
    FakeAllocator gpu;
    TexturePool pool{gpu};
    RecordingExecutor executor;
    FrameGraph graph{{.size = {640, 360}}};
    TextureHandle color = graph.declareTexture("scene.color", kHdr);
    TextureHandle glow{};

    // scene, then two glow passes (declared inside `group`), then the present pass outside it.
    void declare(const PassGroup& group) {
        graph.addPass("scene").writeColor(color);
        {
            PassGroup::Scope in(graph, group);
            Pass& extract = graph.addPass("extract").read(color);
            TextureHandle bright = extract.create("glow.bright", kHdr, TextureUsage::ColorAttachment);
            Pass& blur = graph.addPass("blur").read(bright);
            glow = blur.create("glow.result", kHdr, TextureUsage::ColorAttachment);
        }
        graph.addPass("present").read(color).read(glow).writeColor(graph.output());
    }
};

TEST(PassGroup, TimesAndNamesItsOwnPassesAndTexturesOnly) {
    PassGroup glowGroup;
    GlowFrame frame;
    frame.declare(glowGroup);
    ASSERT_TRUE(frame.graph.execute(frame.pool, frame.executor).ok());
    const FrameReport& report = frame.graph.report();
    EXPECT_EQ(glowGroup.passes(report), (Names{"extract", "blur"}));
    EXPECT_EQ(glowGroup.textures(report), (Names{"glow.bright", "glow.result"}));
    // The fake executor times every pass 0.25 ms: two passes in the group, four in the frame.
    EXPECT_DOUBLE_EQ(glowGroup.timeMs(report), 0.5);
    EXPECT_DOUBLE_EQ(report.timedMs(), 1.0);
    // Another group (even one declared nowhere) owns nothing here.
    PassGroup other;
    EXPECT_TRUE(other.passes(report).empty());
    EXPECT_DOUBLE_EQ(other.timeMs(report), 0.0);
    EXPECT_NE(other.id(), glowGroup.id());
}

TEST(PassGroup, ScopesNestAndRestoreTheOuterGroup) {
    PassGroup outer, inner;
    FrameGraph graph({.size = {64, 64}});
    {
        PassGroup::Scope a(graph, outer);
        graph.addPass("outer 1");
        {
            PassGroup::Scope b(graph, inner);
            graph.addPass("inner");
        }
        graph.addPass("outer 2");
    }
    graph.addPass("none");
    EXPECT_EQ(graph.pass(0).group(), outer.id());
    EXPECT_EQ(graph.pass(1).group(), inner.id());
    EXPECT_EQ(graph.pass(2).group(), outer.id());
    EXPECT_EQ(graph.pass(3).group(), 0u);
}

TEST(PassNeeds, AnUnmetRequirementCullsThePassWithTheGraphsReason) {
    PassGroup glowGroup;
    glowGroup.needing("glow feature");
    GlowFrame frame;
    frame.graph.setUnmet("glow feature", "scene asks for no glow");
    frame.declare(glowGroup);
    ASSERT_TRUE(frame.graph.execute(frame.pool, frame.executor).ok());
    const FrameReport& report = frame.graph.report();
    for (const char* name : {"extract", "blur"}) {
        const PassRecord* p = report.findPass(name);
        ASSERT_NE(p, nullptr) << name;
        EXPECT_EQ(p->status, PassStatus::NotCalledFor) << name;
        EXPECT_EQ(p->reason, "scene asks for no glow") << name;
        EXPECT_FALSE(p->executed) << name;
    }
    // A pass that reads what they would make has lost its input (a lesson presents the scene instead,
    // asking graph.meets() first).
    EXPECT_EQ(report.findPass("present")->status, PassStatus::MissingInput);
}

TEST(PassNeeds, AMetRequirementChangesNothing) {
    PassGroup glowGroup;
    glowGroup.needing("glow feature");
    GlowFrame frame;
    frame.graph.setUnmet("another feature", "not this one");
    frame.declare(glowGroup);
    ASSERT_TRUE(frame.graph.execute(frame.pool, frame.executor).ok());
    EXPECT_TRUE(frame.graph.report().findPass("blur")->executed);
    EXPECT_TRUE(frame.graph.meets("glow feature"));
    EXPECT_FALSE(frame.graph.meets("another feature"));
}

TEST(PassNeeds, TheScenesReasonWinsOverTheStepsSwitch) {
    FrameGraph graph({.size = {64, 64}});
    graph.setUnmet("bloom", "scene has no bloom");
    Pass& pass =
        graph.addPass("bloom").writeColor(graph.output()).needs("bloom").disable("disabled in step 1");
    EXPECT_EQ(pass.switchState(), PassSwitch::NotCalledFor);
    EXPECT_EQ(pass.switchReason(), "scene has no bloom");
}

}  // namespace
}  // namespace fx
