// A scene's post effects as the settings lesson parameters start from: every field of every effect
// present, by its path in the file, as text that reads back as the same value (infinity as the word).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <limits>

#include "scene/scene_enums.hpp"
#include "scene/scene_post.hpp"
#include "scene/scene_settings.hpp"

namespace {

std::string textOf(const std::vector<fx::SettingText>& settings, const std::string& path) {
    for (const auto& s : settings)
        if (s.setting == path) return s.text;
    return "(absent)";
}

TEST(ScenePostSettings, OnlyTheEffectsPresentAndEveryFieldOfThem) {
    fx::Scene scene;
    EXPECT_TRUE(fx::sceneSettings(scene).empty());
    scene.postEffects.bloom = fx::BloomSettings{1.25f, 0.3f, 2.0f, 7};
    scene.postEffects.toneMap = fx::ToneMapSettings{fx::ToneCurve::reinhard, 0.5f};
    auto settings = fx::sceneSettings(scene);
    EXPECT_EQ(settings.size(), 6u);
    EXPECT_EQ(textOf(settings, "postEffects.bloom.threshold"), "1.25");
    EXPECT_EQ(textOf(settings, "postEffects.bloom.levels"), "7");
    EXPECT_EQ(textOf(settings, "postEffects.toneMap.operator"), "reinhard");
    EXPECT_EQ(textOf(settings, "postEffects.toneMap.exposure"), "0.5");
    EXPECT_EQ(textOf(settings, "postEffects.radialBlur.taps"), "(absent)");
}

TEST(ScenePostSettings, NumbersReadBackAsTheSameFloat) {
    fx::Scene scene;
    scene.postEffects.radialBlur = fx::RadialBlurSettings{{0.1f, 0.7f}, 0.0123457f, 0.2f, 8};
    auto settings = fx::sceneSettings(scene);
    for (const char* path : {"postEffects.radialBlur.center[0]", "postEffects.radialBlur.center[1]",
                             "postEffects.radialBlur.length"}) {
        SCOPED_TRACE(path);
        std::string text = textOf(settings, path);
        ASSERT_NE(text, "(absent)");
        float back = static_cast<float>(std::strtod(text.c_str(), nullptr));
        float expected = std::string(path).ends_with("[0]")   ? 0.1f
                         : std::string(path).ends_with("[1]") ? 0.7f
                                                              : 0.0123457f;
        EXPECT_EQ(back, expected);
    }
}

TEST(ScenePostSettings, PathsCoverEveryFieldOnce) {
    auto paths = fx::sceneSettingPaths();
    EXPECT_EQ(paths.size(),
              (4u + 2u + 5u + 2u + 2u) + 4u + 6u);  // post effects, the lens, the first cloud layer
    auto sorted = paths;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());
    EXPECT_NE(std::find(paths.begin(), paths.end(), "postEffects.depthOfField.maxCoc"), paths.end());
}

TEST(ScenePostSettings, InfinityIsWrittenAsTheWord) {
    EXPECT_EQ(fx::settingNumberText(std::numeric_limits<float>::infinity()), "infinity");
    fx::Scene scene;
    scene.camera.lens = fx::Lens{50.0f, 36.0f, 2.8f, std::numeric_limits<float>::infinity()};
    auto settings = fx::sceneSettings(scene);
    EXPECT_EQ(textOf(settings, "camera.lens.focusDistance"), "infinity");
}

// Scene files and lesson parameters spell tone curves the same way, in the enumerators' order.
TEST(ScenePostSettings, ToneCurveNamesFollowTheEnumeration) {
    EXPECT_EQ(fx::enumNameList<fx::ToneCurve>(), (std::vector<std::string>{"clip", "reinhard", "filmic"}));
    EXPECT_EQ(fx::enumFromName<fx::ToneCurve>("filmic"), fx::ToneCurve::filmic);
    EXPECT_EQ(int(fx::ToneCurve::filmic), 2);  // the shader's `curve` uniform (output_transform.glsl)
}

}  // namespace
