// Per-vertex lighting on a big floor quad (the Deferred rendering chapter's pitfall, lesson 10 step 4's
// lighting=per-vertex), read back as floats: the floor is 2 triangles and 4 vertices, 20 m across, and a
// point light of radius 4 m stands 1 m above its middle. Per pixel (the deferred pass) the light makes
// a pool with a highlight under the lamp; per vertex the light is evaluated at the 4 corners, all out
// of its reach, and interpolated: the floor stays as dark as without the lamp. A lamp over a corner
// shows that the per-vertex pass does light what its vertices see.
#include <optional>

#include "effects/deferred/per_vertex_lighting.hpp"
#include "test_deferred_harness.hpp"

using namespace fx;
using namespace fx::test;

namespace {

class PerVertexLightingOnGl : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        auto parsed =
            parseScene(R"({"version": 1, "name": "floor", "background": [0, 0, 0], "ambient": [0, 0, 0],
          "camera": {"position": [0, 12, 12], "target": [0, 0, 0], "fovY": 60, "near": 0.1, "far": 100},
          "lights": [{"type": "directional", "name": "sun", "direction": [0, -1, 0], "color": [1, 1, 1],
                      "intensity": 0}],
          "objects": [{"name": "floor", "primitive": {"shape": "plane", "size": [20, 20]},
                       "material": {"baseColor": [0.6, 0.6, 0.6]}}]})",
                       "floor.json");
        ASSERT_TRUE(parsed.ok()) << parsed.error();
        scene = std::move(*parsed);
        meshes.emplace(scene);
        ASSERT_TRUE(programsBuilt());
    }

    struct Pictures {
        FloatImage perPixel, perVertex;
    };
    Pictures render(glm::vec3 lamp) {
        lights.upload({{glm::vec4(lamp, 4.0f), glm::vec4(1, 1, 1, 0)}});
        GlFrameRunner runner(kSize);
        Pictures p;
        const World world(scene, *meshes, 0.0);
        p.perPixel = runner.frameAndRead([&](FrameGraph& graph) {
            GBufferTargets g = gbuffer.declare(graph, world, {GBufferLayout::compact, false, {}});
            return lighting.declare(graph, scene, g, lights, DeclaredShadowMap{}, std::nullopt);
        });
        p.perVertex =
            runner.frameAndRead([&](FrameGraph& graph) { return perVertex.declare(graph, world, lights); });
        return p;
    }

    // The largest colour channel (not alpha) of any texel.
    static float brightest(const FloatImage& image) {
        float m = 0.0f;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                for (int c = 0; c < 3; ++c) m = std::max(m, image.texel(x, y, c));
        return m;
    }

    static constexpr Size2D kSize{96, 54};
    Scene scene;
    std::optional<SceneMeshes> meshes;
    GBufferPass gbuffer;
    DeferredLighting lighting;
    PerVertexLighting perVertex;
    PointLightBuffer lights;
};

}  // namespace

TEST_F(PerVertexLightingOnGl, ALampOverTheMiddleOfABigFloorQuadIsLostPerVertex) {
    Pictures middle = render({0.0f, 1.0f, 0.0f});
    ASSERT_FALSE(middle.perPixel.empty() || middle.perVertex.empty());
    const float pixelPeak = brightest(middle.perPixel), vertexPeak = brightest(middle.perVertex);
    std::printf("the lamp over the middle: brightest %.4f per pixel, %.4f per vertex\n", pixelPeak,
                vertexPeak);
    // Under the lamp: 0.6 x lambert 1 plus the highlight, attenuated by (1 - (1/4)^2)^2 = 0.88 at 1 m.
    EXPECT_GT(pixelPeak, 0.3f) << "the deferred pass lights the floor under the lamp";
    EXPECT_LT(vertexPeak, 1e-3f) << "per vertex, the 4 corners are out of the lamp's reach: no light at all";

    // Over a corner the vertex there is lit, and the light spreads from it over the triangles.
    Pictures corner = render({10.0f, 1.0f, 10.0f});
    ASSERT_FALSE(corner.perVertex.empty());
    EXPECT_GT(brightest(corner.perVertex), 0.3f) << "a lamp over a vertex lights it per vertex too";
}
