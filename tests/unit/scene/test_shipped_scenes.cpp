// The scenes in res/scenes, every file found there (a new scene needs no edit here): each loads without
// a warning, refers only to files that exist under res/, survives a save and a load, and the lessons'
// scenes call for what their lessons teach. Some referenced files are written by the asset generator
// (tools/assetgen) and committed; kGeneratedAssets says which.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "scene/scene_features.hpp"
#include "scene/scene_loader.hpp"
#include "scene/scene_writer.hpp"
#include "scene_test_support.hpp"

namespace {

namespace fs = std::filesystem;
using fx::SceneFeature;

// Files under res/ that tools/assetgen generates (the fxlab_assets target) and that shipped scenes use.
const std::set<std::string> kGeneratedAssets = {
    "models/character.gltf",        // skinned, with an animation clip named "walk"
    "textures/ground_checker.png",  // ground texture
    "textures/fire_sprite.png",     // the fire particle's alpha shape (lesson 07)
    "textures/cloud_density.png",   // the Clouds chapter's density texture
};

fs::path scenesDir() {
    return scene_test::resDir() / "scenes";
}

// Every scene file in res/scenes, by name, sorted.
std::vector<std::string> shippedScenes() {
    std::vector<std::string> files;
    for (const auto& entry : fs::directory_iterator(scenesDir()))
        if (entry.path().extension() == ".json") files.push_back(entry.path().filename().string());
    std::sort(files.begin(), files.end());
    return files;
}

fx::SceneLoadOptions resOptions(bool checkFiles) {
    fx::SceneLoadOptions options;
    options.assetRoot = scene_test::resDir();
    options.checkFilesExist = checkFiles;
    return options;
}

fx::Scene loadShipped(const std::string& file) {
    auto scene = fx::loadScene(scenesDir() / file, resOptions(false));
    EXPECT_TRUE(scene.ok()) << (scene.ok() ? "" : scene.error());
    if (!scene.ok()) return {};
    EXPECT_TRUE(scene->warnings.empty()) << file << " has warnings, the first: " << scene->warnings.front();
    return *scene;
}

TEST(ShippedScenes, LoadAndReferOnlyToFilesUnderRes) {
    const fs::path res = fs::weakly_canonical(scene_test::resDir());
    for (const std::string& file : shippedScenes()) {
        SCOPED_TRACE(file);
        fx::Scene scene = loadShipped(file);
        for (const auto& referenced : fx::referencedFiles(scene)) {
            const fs::path relative = referenced.lexically_relative(res);
            EXPECT_FALSE(relative.empty() || *relative.begin() == "..") << referenced << " is outside res/";
            EXPECT_TRUE(fs::exists(referenced)) << relative << " is missing";
        }
    }
}

TEST(ShippedScenes, TheyAreFound) {
    // The lessons' ten scenes at least: a test that finds no files checks nothing.
    EXPECT_GE(shippedScenes().size(), 10u);
}

TEST(ShippedScenes, GeneratedAssetsAreCommitted) {
    const fs::path res = scene_test::resDir();
    for (const auto& file : kGeneratedAssets)
        EXPECT_TRUE(fs::exists(res / file)) << file << ": run `cmake --build build --target fxlab_assets`";
}

TEST(ShippedScenes, LoadWithTheExistenceCheckOn) {
    for (const std::string& file : shippedScenes()) {
        SCOPED_TRACE(file);
        auto scene = fx::loadScene(scenesDir() / file, resOptions(true));
        EXPECT_TRUE(scene.ok()) << scene.error();
    }
}

TEST(ShippedScenes, SurviveSaveAndLoad) {
    for (const std::string& file : shippedScenes()) {
        SCOPED_TRACE(file);
        fx::Scene scene = loadShipped(file);
        auto again = fx::parseScene(fx::saveScene(scene), scene.file, resOptions(false));
        ASSERT_TRUE(again.ok()) << again.error();
        EXPECT_TRUE(*again == scene);
    }
}

TEST(ShippedScenes, ProgramObjectsIsPlain) {
    fx::SceneFeatures f = fx::features(loadShipped("01_program_objects.json"));
    EXPECT_FALSE(f.has(SceneFeature::particles));
    EXPECT_FALSE(f.has(SceneFeature::clouds));
    EXPECT_EQ(f.missingReason(SceneFeature::particles), "scene has no particle emitter");
    EXPECT_EQ(f.missingReason(SceneFeature::clouds), "scene has no cloud layer");
    EXPECT_FALSE(f.has(SceneFeature::skinnedMeshes));
    EXPECT_FALSE(f.has(SceneFeature::shadows));
    EXPECT_FALSE(f.has(SceneFeature::hdrEmissive));
    EXPECT_EQ(f.postEffects, fx::PostEffects{});
}

TEST(ShippedScenes, CloudsHasTheChaptersLayerAndASunThatCastsShadows) {
    fx::Scene scene = loadShipped("08_clouds.json");
    fx::SceneFeatures f = fx::features(scene);
    EXPECT_EQ(f.cloudLayers, 1);
    EXPECT_EQ(f.shadowCastingLights, 1);
    const fx::CloudLayer& layer = scene.clouds.at(0);
    // The Clouds chapter's slab (0 to 2 m), scales (1/311, 1/127), threshold and sample count.
    EXPECT_EQ(layer.bottom, 0.0f);
    EXPECT_EQ(layer.top, 2.0f);
    EXPECT_NEAR(layer.noise[0].scale, 1.0f / 311.0f, 1e-6f);
    EXPECT_NEAR(layer.noise[1].scale, 1.0f / 127.0f, 1e-6f);
    EXPECT_EQ(layer.threshold, 0.5f);
    EXPECT_EQ(layer.steps, 8);
}

TEST(ShippedScenes, SkinnedShadowsHasASkinnedMeshAndASun) {
    fx::Scene scene = loadShipped("02_skinned_shadows.json");
    fx::SceneFeatures f = fx::features(scene);
    EXPECT_EQ(f.skinnedMeshes, 2);  // the character and the lattice mannequin (the cut-out caster)
    EXPECT_EQ(f.shadowCastingLights, 1);
    auto character = std::find_if(scene.objects.begin(), scene.objects.end(),
                                  [](const fx::SceneObject& o) { return o.skinned; });
    ASSERT_NE(character, scene.objects.end());
    EXPECT_EQ(character->gltf.path, "../models/character.gltf");
    EXPECT_EQ(character->animation.clips, std::vector<std::string>{"walk"});
    // A low sun: less than 30 degrees above the horizon, for long shadows.
    glm::vec3 d = glm::normalize(scene.lights.at(0).direction);
    EXPECT_LT(std::asin(-d.y), glm::radians(30.0f));
    int props = 0;
    for (const auto& object : scene.objects)
        if (object.primitive && object.primitive->shape != fx::PrimitiveShape::plane && object.castsShadows)
            ++props;
    EXPECT_GE(props, 3);
    EXPECT_EQ(f.missingReason(SceneFeature::particles), "scene has no particle emitter");
}

TEST(ShippedScenes, FboPipelineHasShadowsAndALens) {
    fx::SceneFeatures f = fx::features(loadShipped("03_fbo_pipeline.json"));
    EXPECT_TRUE(f.has(SceneFeature::skinnedMeshes));
    EXPECT_TRUE(f.has(SceneFeature::shadows));
    EXPECT_TRUE(f.has(SceneFeature::physicalLens));
    EXPECT_TRUE(f.has(SceneFeature::depthOfField));
}

TEST(ShippedScenes, ColourMatrixHasSaturatedPrimariesAndWhite) {
    fx::Scene scene = loadShipped("04_colour_matrix.json");
    EXPECT_TRUE(fx::features(scene).has(SceneFeature::colorMatrix));
    // Each object's colour: white, yellow (red and green), or one primary well above the other two.
    std::set<std::string> kinds;
    for (const auto& object : scene.objects) {
        glm::vec3 c = object.material.baseColor;
        if (std::min({c.r, c.g, c.b}) > 0.9f)
            kinds.insert("white");
        else if (c.r > 0.8f && c.g > 0.8f && c.b < 0.1f)
            kinds.insert("yellow");
        else if (c.r > 0.8f && c.g < 0.1f && c.b < 0.1f)
            kinds.insert("red");
        else if (c.g > 0.7f && c.r < 0.1f && c.b < 0.1f)
            kinds.insert("green");
        else if (c.b > 0.8f && c.r < 0.1f && c.g < 0.15f)
            kinds.insert("blue");
    }
    EXPECT_EQ(kinds, (std::set<std::string>{"red", "green", "blue", "yellow", "white"}));
}

TEST(ShippedScenes, RadialBlurHasRowsReceding) {
    fx::Scene scene = loadShipped("05_radial_blur.json");
    EXPECT_TRUE(fx::features(scene).has(SceneFeature::radialBlur));
    int pillars = 0;
    float nearest = 1e9f, farthest = -1e9f;
    for (const auto& object : scene.objects) {
        if (!object.primitive || object.primitive->shape != fx::PrimitiveShape::cylinder) continue;
        ++pillars;
        float distance = glm::length(object.transform.position - scene.camera.position);
        nearest = std::min(nearest, distance);
        farthest = std::max(farthest, distance);
    }
    EXPECT_GE(pillars, 12);
    EXPECT_GT(farthest, 4.0f * nearest);
}

TEST(ShippedScenes, BloomHasHdrEmissiveAndMovingGlows) {
    fx::Scene scene = loadShipped("06_bloom.json");
    fx::SceneFeatures f = fx::features(scene);
    EXPECT_TRUE(f.has(SceneFeature::bloom));
    EXPECT_GE(f.hdrEmissiveObjects, 2);
    // A moving glow, and the firefly lesson 06 uses to show flicker.
    EXPECT_EQ(f.movingObjects, 2);
    for (const auto& object : scene.objects) {
        if (!object.moves()) continue;
        glm::vec3 emitted = object.material.emitted();
        EXPECT_GT(std::max({emitted.r, emitted.g, emitted.b}), 1.0f) << "the moving object should glow";
    }
    // A dim scene: no light brighter than the fill except the spotlight on the white ball.
    EXPECT_LT(scene.ambient.r, 0.05f);
    EXPECT_FALSE(f.has(SceneFeature::particles));
}

TEST(ShippedScenes, DefaultAssetRootIsRes) {
    const char* overrideRoot = std::getenv("FXLAB_ROOT");
    if (overrideRoot && *overrideRoot) GTEST_SKIP() << "FXLAB_ROOT is set";
    EXPECT_EQ(fx::defaultAssetRoot(), scene_test::resDir());
    auto scene = fx::loadScene(scenesDir() / "01_program_objects.json");
    EXPECT_TRUE(scene.ok()) << scene.error();
}

}  // namespace

TEST(ShippedScenes, FireEmitterHasTheChaptersFireSmokeAndSparks) {
    fx::Scene scene = loadShipped("07_fire_emitter.json");
    EXPECT_TRUE(fx::features(scene).has(SceneFeature::particles));
    EXPECT_TRUE(fx::features(scene).has(SceneFeature::bloom));
    ASSERT_EQ(scene.emitters.size(), 3u);
    // The Shader effects chapter's fire: one every 0.2 s, 1 s of life, 0.5 m growing to 2 m, 2 m/s up,
    // emission (3, 0.8, 0.2) fading from alpha 1 to 0, at (-2, 0.7, -4).
    const fx::ParticleEmitter& fire = scene.emitters[0];
    EXPECT_EQ(fire.kind, fx::EmitterKind::fire);
    EXPECT_EQ(fire.position, glm::vec3(-2.0f, 0.7f, -4.0f));
    EXPECT_EQ(fire.ratePerSecond, 5.0f);
    EXPECT_EQ(fire.lifetimeSeconds, 1.0f);
    EXPECT_EQ(fire.startSize, 0.5f);
    EXPECT_EQ(fire.endSize, 2.0f);
    EXPECT_EQ(fire.riseSpeed, 2.0f);
    EXPECT_EQ(fire.startColor, glm::vec4(3.0f, 0.8f, 0.2f, 1.0f));
    EXPECT_EQ(fire.endColor, glm::vec4(3.0f, 0.8f, 0.2f, 0.0f));
    EXPECT_EQ(fire.sprite.path, "../textures/fire_sprite.png");
    EXPECT_EQ(scene.emitters[1].kind, fx::EmitterKind::smoke);
    EXPECT_EQ(scene.emitters[2].kind, fx::EmitterKind::sparks);
}

TEST(ShippedScenes, DeferredShadingHasAThousandLightsAndOneMirror) {
    fx::Scene scene = loadShipped("10_deferred_shading.json");
    fx::SceneFeatures f = fx::features(scene);
    EXPECT_EQ(f.lights, 1 + 1024);  // the moon and a 32 x 32 grid
    EXPECT_TRUE(f.has(SceneFeature::manyLights));
    EXPECT_TRUE(f.has(SceneFeature::shadows));
    EXPECT_EQ(f.mirrors, 1);
    EXPECT_EQ(fx::allLights(scene).size(), 1025u);
}
