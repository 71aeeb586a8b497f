// Every scene setting a lesson parameter may start from, in one list: the post effects, the camera's
// physical lens (lesson 09) and the first cloud layer (lesson 08), each present only when the scene
// has it, and every path the list can name known even when this scene lacks it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "scene/scene_settings.hpp"

namespace {

std::string textOf(const std::vector<fx::SettingText>& settings, const std::string& path) {
    for (const auto& s : settings)
        if (s.setting == path) return s.text;
    return "(absent)";
}

bool known(const std::string& path) {
    auto paths = fx::sceneSettingPaths();
    return std::find(paths.begin(), paths.end(), path) != paths.end();
}

TEST(SceneSettings, TheLensStartsParametersOnlyWhenTheCameraHasOne) {
    fx::Scene scene;
    EXPECT_EQ(textOf(fx::sceneSettings(scene), "camera.lens.focalLength"), "(absent)");
    scene.camera.lens = fx::Lens{31.1769f, 36.0f, 1.4f, 15.264f};
    auto settings = fx::sceneSettings(scene);
    EXPECT_EQ(textOf(settings, "camera.lens.focalLength"), "31.1769");
    EXPECT_EQ(textOf(settings, "camera.lens.sensorWidth"), "36");
    EXPECT_EQ(textOf(settings, "camera.lens.fNumber"), "1.4");
    EXPECT_EQ(textOf(settings, "camera.lens.focusDistance"), "15.264");
}

TEST(SceneSettings, PostEffectsLensAndCloudsInOneList) {
    fx::Scene scene;
    scene.postEffects.bloom = fx::BloomSettings{};
    scene.camera.lens = fx::Lens{};
    scene.clouds.push_back(fx::CloudLayer{});
    scene.clouds.back().steps = 12;
    auto settings = fx::sceneSettings(scene);
    EXPECT_NE(textOf(settings, "postEffects.bloom.threshold"), "(absent)");
    EXPECT_NE(textOf(settings, "camera.lens.fNumber"), "(absent)");
    EXPECT_EQ(textOf(settings, "clouds[0].steps"), "12");
}

TEST(SceneSettings, EveryPathIsKnownWhateverTheSceneHas) {
    for (const char* path :
         {"postEffects.bloom.threshold", "postEffects.toneMap.operator", "camera.lens.focalLength",
          "camera.lens.focusDistance", "clouds[0].threshold", "clouds[0].noise[1].scale"}) {
        SCOPED_TRACE(path);
        EXPECT_TRUE(known(path));
    }
    EXPECT_FALSE(known("camera.lens.aperture"));
}

// One range: a parameter made from a setting takes both ends of what a scene file may hold (bloom
// levels up to the chain's 8, a focus distance up to infinity), and what the setting refuses it refuses.
TEST(SceneSettings, AParameterTakesEveryValueItsSettingAllows) {
    for (const fx::SettingSpec& spec : fx::sceneSettingSpecs()) {
        SCOPED_TRACE(spec.path);
        fx::ParamSet params;
        float number = 0.0f;
        int whole = 0;
        fx::Param& p = spec.type == fx::ParamType::Float ? params.addSetting("p", &number, spec)
                                                         : params.addSetting("p", &whole, spec);
        EXPECT_EQ(p.min, spec.min);
        EXPECT_EQ(p.max, spec.max);
        EXPECT_EQ(p.sceneSetting, spec.path);
        for (double end : {spec.min, spec.max}) {
            EXPECT_TRUE(params.assign("p=" + spec.valueText(end)).ok()) << spec.valueText(end);
        }
        if (spec.type != fx::ParamType::Choice && !std::isinf(spec.max)) {
            EXPECT_FALSE(params.assign("p=" + spec.valueText(spec.max + 1)).ok());
        }
    }
    float focus = 0.0f;
    fx::ParamSet params;
    params.addSetting("focus_distance", &focus, fx::sceneSetting("camera.lens.focusDistance"));
    ASSERT_TRUE(params.assign("focus_distance=100000").ok());
    ASSERT_TRUE(params.assign("focus_distance=infinity").ok());
    EXPECT_TRUE(std::isinf(focus));
}

}  // namespace
