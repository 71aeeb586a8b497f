// The scene settings' ranges (scene/scene_settings.cpp, in a layer below the effects) end where the
// effects end: as many bloom levels as the chain makes, radial blur taps as the blur takes, cloud
// samples as the march takes. A limit changed on one side fails here.
#include <gtest/gtest.h>

#include "effects/bloom/bloom_levels.hpp"
#include "effects/clouds/cloud_march.hpp"
#include "effects/post/radial_blur.hpp"
#include "scene/scene_settings.hpp"

namespace {

TEST(SettingLimits, TheSettingsEndWhereTheEffectsEnd) {
    EXPECT_EQ(fx::sceneSetting("postEffects.bloom.levels").max, fx::kBloomMaxLevels);
    EXPECT_EQ(fx::sceneSetting("postEffects.radialBlur.taps").max, fx::kRadialBlurMaxSamples);
    EXPECT_EQ(fx::sceneSetting("clouds[0].steps").max, fx::kCloudMaxSteps);
}

}  // namespace
