// "lightGrids": a rectangle of point lights from one entry (lesson 10's thousand lights), read,
// expanded, counted as lights, written back, and refused with the field and the reason when wrong.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include <glm/geometric.hpp>

#include "scene/scene_features.hpp"
#include "scene/scene_loader.hpp"
#include "scene/scene_writer.hpp"
#include "scene_test_support.hpp"

namespace {

using scene_test::contains;

std::string sceneWith(const std::string& grids) {
    return R"({"name": "grid", "camera": {"position": [0, 2, 8], "target": [0, 0, 0]},
               "lights": [{"type": "directional", "direction": [0, -1, 0]}],
               "lightGrids": )" +
           grids + "}";
}

fx::Result<fx::Scene> parse(const std::string& text) {
    return fx::parseScene(text, scene_test::dataDir() / "grid.json", scene_test::testOptions());
}

TEST(SceneLightGrid, ExpandsRowByRowCentredOnItsCentre) {
    auto scene = parse(sceneWith(R"([{"name": "g", "center": [10, 2, -4], "count": [3, 2],
                                      "spacing": [1.5, 4], "radius": 2.5, "intensity": 3}])"));
    ASSERT_TRUE(scene.ok()) << scene.error();
    std::vector<fx::Light> lights = fx::allLights(*scene);
    ASSERT_EQ(lights.size(), 7u);  // the directional light, then 3 x 2
    EXPECT_EQ(lights[0].type, fx::LightType::directional);
    EXPECT_EQ(lights[1].name, "g[0]");
    EXPECT_EQ(lights[1].position, glm::vec3(8.5f, 2.0f, -6.0f));
    EXPECT_EQ(lights[3].position, glm::vec3(11.5f, 2.0f, -6.0f));  // X runs fastest
    EXPECT_EQ(lights[4].position, glm::vec3(8.5f, 2.0f, -2.0f));
    for (std::size_t i = 1; i < lights.size(); ++i) {
        EXPECT_EQ(lights[i].type, fx::LightType::point);
        EXPECT_EQ(lights[i].radius, 2.5f);
        EXPECT_EQ(lights[i].intensity, 3.0f);
    }
    EXPECT_EQ(fx::features(*scene).lights, 7);
    EXPECT_TRUE(fx::features(*scene).has(fx::SceneFeature::manyLights));
}

TEST(SceneLightGrid, ColoursAreHashedHuesWithTheirLargestChannelOne) {
    std::set<int> reddest;
    for (int i = 0; i < 64; ++i) {
        glm::vec3 c = fx::gridLightColor(i, 7, 1.0f);
        EXPECT_FLOAT_EQ(std::max({c.r, c.g, c.b}), 1.0f) << i;
        EXPECT_GE(std::min({c.r, c.g, c.b}), 0.0f) << i;
        reddest.insert(c.r >= c.g && c.r >= c.b ? 0 : c.g >= c.b ? 1 : 2);
        EXPECT_EQ(c, fx::gridLightColor(i, 7, 1.0f));  // the same every time
    }
    EXPECT_EQ(reddest.size(), 3u);                               // the hash spreads the hues round the wheel
    EXPECT_EQ(fx::gridLightColor(5, 7, 0.0f), glm::vec3(1.0f));  // saturation 0: white
    EXPECT_NE(fx::gridLightColor(5, 7, 1.0f), fx::gridLightColor(5, 8, 1.0f));
}

TEST(SceneLightGrid, RoundTripsThroughTheWriter) {
    auto scene = parse(sceneWith(R"([{"center": [0, 1, 0], "count": [32, 32], "spacing": [0.5, 0.75],
                                      "saturation": 0.25, "seed": 42}])"));
    ASSERT_TRUE(scene.ok()) << scene.error();
    auto again = parse(fx::saveScene(*scene));
    ASSERT_TRUE(again.ok()) << again.error();
    ASSERT_EQ(again->lightGrids.size(), 1u);
    EXPECT_EQ(again->lightGrids[0], scene->lightGrids[0]);
    EXPECT_EQ(fx::allLights(*again).size(), 1025u);
}

TEST(SceneLightGrid, BadGridsAreRefusedWithTheFieldAndTheReason) {
    struct Case {
        const char* grids;
        const char* path;
        const char* why;
    };
    const Case cases[] = {
        {R"([{"count": [2, 2]}])", "lightGrids[0].center", "required"},
        {R"([{"center": [0, 1, 0], "count": [0, 2]}])", "lightGrids[0].count[0]", "out of range"},
        {R"([{"center": [0, 1, 0], "count": [2.5, 2]}])", "lightGrids[0].count", "whole numbers"},
        {R"([{"center": [0, 1, 0], "count": [64, 32]}])", "lightGrids[0].count", "at most 1024"},
        {R"([{"center": [0, 1, 0], "count": [32, 20]}, {"center": [0, 1, 0], "count": [32, 20]}])",
         "lightGrids[1].count", "1280 lights together"},
        {R"([{"center": [0, 1, 0], "spacing": [0, 1]}])", "lightGrids[0].spacing[0]", "out of range"},
        {R"([{"center": [0, 1, 0], "radius": 0}])", "lightGrids[0].radius", "range"},
        {R"([{"center": [0, 1, 0], "saturation": 2}])", "lightGrids[0].saturation", "range"},
    };
    for (const Case& c : cases) {
        auto scene = parse(sceneWith(c.grids));
        ASSERT_FALSE(scene.ok()) << c.grids;
        EXPECT_TRUE(contains(scene.error(), std::string(c.path) + ": ")) << scene.error();
        EXPECT_TRUE(contains(scene.error(), c.why)) << scene.error();
    }
    // An unknown field is a warning with the field's path, as everywhere in a scene file.
    auto typo = parse(sceneWith(R"([{"center": [0, 1, 0], "colour": [1, 0, 0]}])"));
    ASSERT_TRUE(typo.ok()) << typo.error();
    ASSERT_EQ(typo->warnings.size(), 1u);
    EXPECT_TRUE(contains(typo->warnings[0], "lightGrids[0].colour: unknown field")) << typo->warnings[0];
}

}  // namespace

namespace {

std::string sceneWithObjects(const std::string& objects) {
    return R"({"name": "mirror", "camera": {"position": [0, 2, 8], "target": [0, 0, 0]}, "objects": )" +
           objects + "}";
}

TEST(SceneMirror, APlaneCanBeTheOneMirror) {
    auto scene = parse(sceneWithObjects(R"([{"name": "floor", "primitive": {"shape": "plane", "size": [4, 4]},
                                             "mirror": {"strength": 0.4}},
                                            {"primitive": {"shape": "box"}}])"));
    ASSERT_TRUE(scene.ok()) << scene.error();
    ASSERT_TRUE(scene->objects[0].mirror.has_value());
    EXPECT_EQ(scene->objects[0].mirror->strength, 0.4f);
    EXPECT_FALSE(scene->objects[1].mirror.has_value());
    EXPECT_TRUE(fx::features(*scene).has(fx::SceneFeature::mirror));
    auto again = parse(fx::saveScene(*scene));
    ASSERT_TRUE(again.ok()) << again.error();
    EXPECT_EQ(again->objects, scene->objects);

    auto plain = parse(sceneWithObjects(R"([{"primitive": {"shape": "plane"}}])"));
    ASSERT_TRUE(plain.ok()) << plain.error();
    EXPECT_EQ(fx::features(*plain).missingReason(fx::SceneFeature::mirror),
              "scene has no mirror (no object with \"mirror\")");
}

TEST(SceneMirror, BadMirrorsAreRefusedWithTheFieldAndTheReason) {
    struct Case {
        const char* objects;
        const char* path;
        const char* why;
    };
    const Case cases[] = {
        {R"([{"primitive": {"shape": "box"}, "mirror": {}}])", "objects[0].mirror", "only a plane primitive"},
        {R"([{"primitive": {"shape": "plane"}, "mirror": {"strength": 1.5}}])", "objects[0].mirror.strength",
         "range"},
        {R"([{"primitive": {"shape": "plane"}, "mirror": {}}, {"primitive": {"shape": "plane"}, "mirror": {}}])",
         "objects[1].mirror", "one mirror"},
    };
    for (const Case& c : cases) {
        auto scene = parse(sceneWithObjects(c.objects));
        ASSERT_FALSE(scene.ok()) << c.objects;
        EXPECT_TRUE(contains(scene.error(), std::string(c.path) + ": ")) << scene.error();
        EXPECT_TRUE(contains(scene.error(), c.why)) << scene.error();
    }
    auto typo = parse(sceneWithObjects(R"([{"primitive": {"shape": "plane"}, "mirror": {"strenght": 1}}])"));
    ASSERT_TRUE(typo.ok()) << typo.error();
    ASSERT_EQ(typo->warnings.size(), 1u);
    EXPECT_TRUE(contains(typo->warnings[0], "objects[0].mirror.strenght: unknown field"))
        << typo->warnings[0];
}

}  // namespace
