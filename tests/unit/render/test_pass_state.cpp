#include <gtest/gtest.h>

#include "render/pass_state.hpp"
#include "render/state_diff.hpp"

namespace fx {
namespace {

GlStateSnapshot sandboxDefaults() {
    GlStateSnapshot s = GlStateSnapshot::glInitial({1280, 720});
    s.depthTest = true;
    s.faceCulling = true;
    return s;
}

std::vector<std::string> texts(const std::vector<StateDifference>& diffs) {
    std::vector<std::string> out;
    for (const auto& d : diffs) out.push_back(d.text());
    return out;
}

TEST(StateDiff, IdenticalStatesHaveNoDifferences) {
    EXPECT_TRUE(diffState(sandboxDefaults(), sandboxDefaults()).empty());
}

TEST(StateDiff, NamesEachDifferenceWithItsDefault) {
    GlStateSnapshot left = sandboxDefaults();
    left.depthTest = false;
    left.blend = true;
    left.blendFunction = BlendFunction::additive();
    left.cullFace = CullFace::Front;
    left.colorMask = {true, true, true, false};
    left.depthFunction = DepthFunction::LessEqual;
    EXPECT_EQ(texts(diffState(left, sandboxDefaults())),
              (std::vector<std::string>{
                  "depth test: off (default on)",
                  "depth function: LessEqual (default Less)",
                  "blend: on (default off)",
                  "blend function: Add(One, One) (default Add(One, Zero))",
                  "cull face: Front (default Back)",
                  "colour mask: RGB- (default RGBA)",
              }));
}

TEST(StateDiff, SeparateAlphaBlendAndViewportAndClears) {
    GlStateSnapshot left = sandboxDefaults();
    left.viewport = {0, 0, 2048, 2048};
    left.blendFunction = BlendFunction::alpha();
    left.clearDepth = 0.5f;
    auto diffs = diffState(left, sandboxDefaults());
    ASSERT_EQ(diffs.size(), 3u);
    EXPECT_EQ(diffs[0].text(), "viewport: 0, 0, 2048x2048 (default 0, 0, 1280x720)");
    EXPECT_EQ(diffs[1].text(),
              "blend function: rgb Add(SrcAlpha, OneMinusSrcAlpha), alpha Add(One, OneMinusSrcAlpha) "
              "(default Add(One, Zero))");
    EXPECT_EQ(diffs[2].field, "clear depth");
    EXPECT_EQ(diffs[2].value, "0.5");
}

TEST(PassState, UnsetFieldsInheritWhatThePreviousPassLeft) {
    // Lesson 03's bug: the post pass turns depth testing off; a shadow pass that relies on the
    // default and runs after it inherits "off".
    GlStateSnapshot afterPost =
        applyPassState(sandboxDefaults(), {.depthTest = false, .blend = false}, {1280, 720});
    PassState shadow{.depthWrite = true, .clearDepth = 1.0f};
    GlStateSnapshot afterShadow = applyPassState(afterPost, shadow, {2048, 2048});
    EXPECT_FALSE(afterShadow.depthTest);
    EXPECT_EQ(texts(diffState(afterShadow, sandboxDefaults())),
              (std::vector<std::string>{"viewport: 0, 0, 2048x2048 (default 0, 0, 1280x720)",
                                        "depth test: off (default on)"}));
    // Declaring it fixes the leak.
    shadow.depthTest = true;
    EXPECT_TRUE(applyPassState(afterPost, shadow, {2048, 2048}).depthTest);
}

TEST(PassState, UnsetViewportMeansTheWholeTarget) {
    GlStateSnapshot before = sandboxDefaults();
    EXPECT_EQ(applyPassState(before, {}, {320, 180}).viewport, (Viewport{0, 0, 320, 180}));
    PassState corner{.viewport = Viewport{10, 20, 30, 40}};
    EXPECT_EQ(applyPassState(before, corner, {320, 180}).viewport, (Viewport{10, 20, 30, 40}));
}

TEST(PassState, ListsInheritedFields) {
    PassState state{.depthTest = true,
                    .depthWrite = true,
                    .depthFunction = DepthFunction::Less,
                    .blend = false,
                    .blendFunction = BlendFunction::replace(),
                    .faceCulling = true,
                    .cullFace = CullFace::Back};
    EXPECT_EQ(inheritedFields(state), (std::vector<std::string_view>{"colour mask"}));
    EXPECT_EQ(inheritedFields({}).size(), 8u);
}

}  // namespace
}  // namespace fx
