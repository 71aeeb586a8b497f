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

TEST(InheritedState, APassThatClearsDepthInheritsTheDepthMaskOffEvenWithoutTesting) {
    // glClear (and glClearBuffer) obey the depth mask: with writes left off by the pass before, the
    // clear does nothing and the pass keeps last frame's depth. A pass that clears depth depends on the
    // mask whether or not it tests, and the check names it as it names the depth test.
    GlStateSnapshot before = afterUiQueue();
    before.depthWrite = false;
    PassState clearsOnly{.depthTest = false, .faceCulling = false, .clearDepth = 1.0f};
    Names names = inheritedDependencies(clearsOnly, before, {.depth = true, .color = false});
    EXPECT_EQ(names, (Names{"depth write: off (inherited)"}));
    // Declared, it is named no more; and a pass that neither clears nor tests does not depend on it.
    clearsOnly.depthWrite = true;
    EXPECT_TRUE(inheritedDependencies(clearsOnly, before, {.depth = true, .color = false}).empty());
    PassState neither{.depthTest = false, .faceCulling = false};
    EXPECT_TRUE(inheritedDependencies(neither, before, {.depth = true, .color = false}).empty());
}

TEST(InheritedState, ColourPassInheritsBlendingAndItsFunction) {
    Names names = inheritedDependencies(PassState{.faceCulling = false}, afterUiQueue(),
                                        {.depth = false, .color = true});
    EXPECT_EQ(names, (Names{"blend: on (inherited)",
                            "blend function: rgb Add(SrcAlpha, OneMinusSrcAlpha), "
                            "alpha Add(One, OneMinusSrcAlpha) (inherited)",
                            "colour mask: RGBA (inherited)"}));
}

TEST(InheritedState, BlendingDeclaredOffMakesTheFunctionIrrelevant) {
    Names names =
        inheritedDependencies(PassState{.blend = false, .faceCulling = false, .colorMask = ColorMask{}},
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
