// FullscreenVariants: one program per set of #define choices, built on first use, each under its own
// label, and a set that does not compile is an unusable pass with the compiler's error, not a crash.
#include <string>

#include "effects/post/fullscreen_variants.hpp"
#include "gl_test.hpp"

using namespace fx;

namespace {

std::string programLabel(GLuint program) {
    char text[256] = {};
    GLsizei length = 0;
    glGetObjectLabel(GL_PROGRAM, program, GLsizei(sizeof text), &length, text);
    return std::string(text, std::size_t(length));
}

}  // namespace

class FullscreenVariantsOnGl : public GlTest {};

TEST_F(FullscreenVariantsOnGl, TheSameChoicesGiveTheSameProgramAndOthersAnother) {
    FullscreenVariants variants("effects/post/output_transform.frag", "test transform");
    EXPECT_EQ(variants.built(), 0u);  // nothing is built before a frame asks
    const FullscreenPass& plain = variants.get({{"SPLIT_VIEW", 0}, {"TONE_CURVE", 0}});
    ASSERT_TRUE(programsBuilt());
    EXPECT_EQ(&variants.get({{"SPLIT_VIEW", 0}, {"TONE_CURVE", 0}}), &plain);
    EXPECT_EQ(variants.built(), 1u);
    const FullscreenPass& filmic = variants.get({{"SPLIT_VIEW", 0}, {"TONE_CURVE", 2}});
    ASSERT_TRUE(programsBuilt());
    EXPECT_NE(filmic.program(), plain.program());
    EXPECT_EQ(variants.built(), 2u);
    EXPECT_EQ(programLabel(filmic.program()), "test transform (SPLIT_VIEW 0, TONE_CURVE 2)");
}

TEST_F(FullscreenVariantsOnGl, AChoiceLeftOutIsACompileErrorThatNamesIt) {
    FullscreenVariants variants("effects/post/output_transform.frag", "test transform");
    expectBrokenPrograms();
    const gl::ReloadableProgram& broken = variants.get({{"SPLIT_VIEW", 1}}).reloadable();
    EXPECT_FALSE(broken.usable());
    EXPECT_NE(broken.error().find("TONE_CURVE"), std::string::npos) << broken.error();
    // The other sets still build: one broken set does not poison the rest.
    EXPECT_TRUE(variants.get({{"SPLIT_VIEW", 1}, {"TONE_CURVE", 1}}).reloadable().usable());
}
