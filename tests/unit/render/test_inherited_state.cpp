// The executor's "state inherited" check (render/state_diff.hpp): which undeclared state a pass
// depends on, named with the value it got from the pass before it.
#include <gtest/gtest.h>

#include "render/state_diff.hpp"

namespace fx {
namespace {

using Names = std::vector<std::string>;

GlStateSnapshot afterUiQueue() {
    // What the chapter's overlay queue leaves for the next frame: no depth test, alpha blending.
    GlStateSnapshot s = GlStateSnapshot::glInitial({320, 180});
    s.depthTest = false;
    s.blend = true;
    s.blendFunction = BlendFunction::alpha();
    return s;
}

TEST(InheritedState, DepthOnlyPassThatDeclaresNothingInheritsTheDepthTestOff) {
    // Shader effects chapter §3.3: the reordered shadow pass.
    Names names = inheritedDependencies(PassState{}, afterUiQueue(), {.depth = true, .color = false});
    EXPECT_EQ(names, (Names{"depth test: off (inherited)", "face culling: off (inherited)"}));
}

TEST(InheritedState, WhileTestingDepthTheWriteAndFunctionMatterToo) {
    GlStateSnapshot before = afterUiQueue();
    before.depthTest = true;
    Names names = inheritedDependencies(PassState{}, before, {.depth = true, .color = false});
    EXPECT_EQ(names, (Names{"depth test: on (inherited)", "depth write: on (inherited)",
                            "depth function: Less (inherited)", "face culling: off (inherited)"}));
}

TEST(InheritedState, ADeclaredDepthTestStillLeavesWriteAndFunctionOpen) {
    PassState state{.depthTest = true};
    Names names = inheritedDependencies(state, afterUiQueue(), {.depth = true, .color = false});
    EXPECT_EQ(names, (Names{"depth write: on (inherited)", "depth function: Less (inherited)",
                            "face culling: off (inherited)"}));
}

TEST(InheritedState, ColourPassInheritsBlendingAndItsFunction) {
    Names names = inheritedDependencies(PassState{.faceCulling = false}, afterUiQueue(),
                                        {.depth = false, .color = true});
    EXPECT_EQ(names, (Names{"blend: on (inherited)", "blend function: rgb Add(SrcAlpha, OneMinusSrcAlpha), "
                                                     "alpha Add(One, OneMinusSrcAlpha) (inherited)",
                            "colour mask: RGBA (inherited)"}));
}

TEST(InheritedState, BlendingDeclaredOffMakesTheFunctionIrrelevant) {
    Names names = inheritedDependencies(PassState{.blend = false, .faceCulling = false, .colorMask = ColorMask{}},
                                        afterUiQueue(), {.depth = false, .color = true});
    EXPECT_TRUE(names.empty()) << names.front();
}

TEST(InheritedState, APassThatDeclaresEverythingItDependsOnInheritsNothing) {
    PassState shadow{.depthTest = true,
                     .depthWrite = true,
                     .depthFunction = DepthFunction::Less,
                     .blend = false,
                     .faceCulling = false,
                     .colorMask = ColorMask{}};
    EXPECT_TRUE(inheritedDependencies(shadow, afterUiQueue(), {.depth = true, .color = true}).empty());
}

TEST(InheritedState, APassThatDrawsNothingDependsOnNothing) {
    EXPECT_TRUE(inheritedDependencies(PassState{}, afterUiQueue(), {}).empty());
}

}  // namespace
}  // namespace fx
