// The shadow map on the real frame graph and GL executor, read back as floats: the character's
// silhouette is in the map only with the skinned shadow program, where the CPU skinning reference puts
// it; both skinning products give the same map; the pass's own state against inherited state; the
// chapter's error flood and its fix; and the hard cases (bad weights, a light parallel to up, casters
// outside the light's frustum, a time far past the clip's length) stay finite.
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "base/paths.hpp"
#include "effects/shadow/shadow_lit_pass.hpp"
#include "effects/shadow/shadow_map.hpp"
#include "gl/debug_output.hpp"
#include "gl/object.hpp"
#include "gl/readback.hpp"
#include "gl/texture.hpp"
#include "gl_test.hpp"
#include "render/frame_graph.hpp"
#include "render/texture_pool.hpp"
#include "render_gl/gl_pass_executor.hpp"
#include "render_gl/gl_texture_allocator.hpp"
#include "render_gl/pass_timer.hpp"
#include "scene/scene_loader.hpp"
#include "scene/skin.hpp"

using namespace fx;

namespace {

constexpr int kMapSize = 512;
constexpr Size2D kOutput{96, 64};

Scene loadLessonScene() {
    SceneLoadOptions options;
    options.assetRoot = resourceDir();
    auto scene = loadScene(resourceDir() / "scenes/02_skinned_shadows.json", options);
    EXPECT_TRUE(scene.ok()) << (scene.ok() ? "" : scene.error());
    return scene.ok() ? std::move(*scene) : Scene{};
}

std::size_t characterIndex(const Scene& scene) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].name == "character") return i;
    return scene.objects.size();
}

int texelsBelow(const FloatImage& depth, float limit) {
    return int(std::count_if(depth.texels.begin(), depth.texels.end(), [&](float v) { return v < limit; }));
}

struct FrameResult {
    FloatImage map;
    std::optional<FloatImage> color;
    LightView light;
    ShadowPassStats stats;
    bool mapPassExists = false;
};

}  // namespace

class ShadowMapTest : public GlTest {
protected:
    Scene scene;
    std::optional<SceneMeshes> meshes;
    ShadowMap shadows;
    ShadowLitPass lit;

    void SetUp() override {
        GlTest::SetUp();
        scene = loadLessonScene();
        meshes.emplace(scene);
        ASSERT_TRUE(programsBuilt());
    }
    void TearDown() override {
        meshes.reset();
        GlTest::TearDown();
    }

    // One frame: the shadow pass (and the lit pass when `withColor`), the map read back.
    FrameResult run(double seconds, ShadowPassOptions options, bool withColor = false,
                    std::optional<LightView> light = std::nullopt, std::function<void()> before = {}) {
        FrameResult result;
        GlTextureAllocator allocator;
        TexturePool pool(allocator);
        PassTimer timer(TimingMode::Off, "");
        GlPassExecutor executor(timer, {context().presentFramebuffer(), true});
        FrameGraph graph(OutputTarget{kOutput, "output", TextureFormat::RGBA8, 0});
        ShadowSettings settings;
        settings.casts = true;
        settings.mapSize = kMapSize;
        settings.filterTaps = 4;
        settings.extent = 15.0f;
        options.stats = &result.stats;
        meshes->update(seconds);
        DeclaredShadowMap map =
            light ? shadows.declare(graph, World(scene, *meshes, seconds), settings, *light, options)
                  : shadows.declare(graph, World(scene, *meshes, seconds), settings, options);
        result.light = map.lookup.light;
        result.mapPassExists = map.pass != nullptr;
        if (!map.pass) return result;
        graph.capture(map.map);
        HdrSceneTargets hdr;
        if (withColor) {
            hdr = lit.declare(graph, World(scene, *meshes, seconds), map, options.skinnedPlacements);
            graph.capture(hdr.color);
        }
        if (before) before();
        Status status = graph.execute(pool, executor);
        EXPECT_TRUE(status.ok()) << (status.ok() ? "" : status.error());
        const TextureView& view = graph.texture(map.map);
        result.map = gl::readTexture(view.native, view.spec);
        if (withColor) {
            const TextureView& c = graph.texture(hdr.color);
            result.color = gl::readTexture(c.native, c.spec);
        }
        graph.releaseTextures();
        glBindVertexArray(0);
        glUseProgram(0);
        return result;
    }

    // The character's vertices posed on the CPU (scene/skin.hpp), in world space.
    std::vector<glm::vec3> cpuCharacterVertices(double seconds) {
        std::vector<glm::vec3> out;
        std::size_t index = characterIndex(scene);
        const GpuModel* gpu = meshes->model(index);
        if (!gpu) return out;
        meshes->update(seconds);
        const GltfModel& model = gpu->model();
        glm::mat4 object = SceneMeshes::modelAt(scene.objects[index], seconds);
        for (int node : model.meshNodes()) {
            const ModelNode& n = model.nodes[std::size_t(node)];
            const std::vector<glm::mat4>& palette = gpu->jointMatrices(node);
            glm::mat4 world = object * gpu->nodeWorld()[std::size_t(node)];
            for (const ModelPrimitive& prim : model.meshes[std::size_t(n.mesh)].primitives) {
                if (!prim.skinned()) continue;
                for (std::size_t v = 0; v < prim.mesh.positions.size(); ++v) {
                    glm::mat4 skin = blendJoints(prim.influences[v], palette);
                    out.push_back(glm::vec3(world * (skin * glm::vec4(prim.mesh.positions[v], 1.0f))));
                }
            }
        }
        return out;
    }
};

namespace {

// Of the vertices, the fraction whose texel (or a neighbour, for rasterisation at edges) holds a depth
// no farther than the vertex: where the map has the vertex's surface, or something nearer the light.
double fractionCovered(const FloatImage& map, const LightView& light,
                       const std::vector<glm::vec3>& vertices) {
    if (vertices.empty()) return 0.0;
    int covered = 0;
    for (const glm::vec3& v : vertices) {
        glm::vec4 clip = light.viewProjection * glm::vec4(v, 1.0f);
        glm::vec3 c = glm::vec3(clip) / clip.w * 0.5f + 0.5f;
        int x = int(std::floor(c.x * float(map.width))), y = int(std::floor(c.y * float(map.height)));
        float nearest = 1.0f;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                int xx = std::clamp(x + dx, 0, map.width - 1), yy = std::clamp(y + dy, 0, map.height - 1);
                nearest = std::min(nearest, map.texels[std::size_t(yy * map.width + xx)]);
            }
        // Three texels of depth slack: a neighbour texel on a surface that slopes away from the light
        // is that much farther. A limb posed wrongly is off by tens of centimetres, far more.
        float slack = 3.0f * light.texelWorldSize / std::max(light.farDistance - light.nearDistance, 1e-3f);
        if (nearest <= c.z + slack) ++covered;
    }
    return double(covered) / double(vertices.size());
}

}  // namespace

TEST_F(ShadowMapTest, CharacterSilhouetteOnlyWithTheSkinnedProgramWhereTheCpuPutsIt) {
    const double t = 0.37;
    std::vector<glm::vec3> vertices = cpuCharacterVertices(t);
    ASSERT_GT(vertices.size(), 100u);

    ShadowPassOptions staticOnly;
    staticOnly.drawSkinned = false;
    FrameResult step1 = run(t, staticOnly);
    FrameResult step2 = run(t, {});
    ASSERT_TRUE(allFinite(step1.map));
    ASSERT_TRUE(allFinite(step2.map));
    EXPECT_EQ(step1.stats.skinnedDraws, 0u);
    EXPECT_EQ(step2.stats.skinnedDraws, 2u);  // the character and the lattice mannequin
    EXPECT_EQ(step2.stats.programSwitches, 1);

    // Step 2: the texels under the CPU-skinned vertices hold the character (or something nearer).
    double inStep2 = fractionCovered(step2.map, step2.light, vertices);
    double inStep1 = fractionCovered(step1.map, step1.light, vertices);
    EXPECT_GT(inStep2, 0.99) << "the skinned shadow does not match the CPU skinning reference";
    EXPECT_LT(inStep1, 0.3) << "the character is in the map without the skinned program";
    // And the character adds drawn texels: its silhouette.
    EXPECT_GT(texelsBelow(step2.map, 1.0f), texelsBelow(step1.map, 1.0f) + 50);
}

TEST_F(ShadowMapTest, BothSkinningProductsGiveTheSameMap) {
    ShadowPassOptions grouped;
    grouped.product = SkinningProduct::grouped;
    FrameResult a = run(0.5, grouped);
    FrameResult b = run(0.5, {});
    ASSERT_EQ(a.map.texels.size(), b.map.texels.size());
    int different = 0;
    for (std::size_t i = 0; i < a.map.texels.size(); ++i)
        different += std::abs(a.map.texels[i] - b.map.texels[i]) > 1e-5f;
    // Rounding may move an edge texel or two; the silhouette is the same.
    EXPECT_LE(different, 20);
    EXPECT_EQ(operationCount(SkinningProduct::grouped).mul, 80);
    EXPECT_EQ(operationCount(SkinningProduct::parenthesised).add, 24);
}

TEST_F(ShadowMapTest, OwnStateWritesDepthWhateverWasLeftAndInheritedStateDoesNot) {
    auto depthTestOff = [] {
        glDisable(GL_DEPTH_TEST);
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    };
    FrameResult own = run(0.5, {}, false, std::nullopt, depthTestOff);
    EXPECT_GT(texelsBelow(own.map, 1.0f), 1000);

    ShadowPassOptions inherits;
    inherits.setsItsOwnState = false;
    FrameResult leaked = run(0.5, inherits, false, std::nullopt, depthTestOff);
    // Shader effects chapter §3.3: with the depth test off GL writes no depth: the map stays cleared.
    EXPECT_EQ(texelsBelow(leaked.map, 1.0f), 0);

    // The declared state itself: nothing about depth or blend when the pass inherits.
    FrameGraph graph(OutputTarget{kOutput, "output", TextureFormat::RGBA8, 0});
    ShadowSettings settings;
    settings.casts = true;
    DeclaredShadowMap map = shadows.declare(graph, World(scene, *meshes, 0.0), settings, inherits);
    ASSERT_NE(map.pass, nullptr);
    EXPECT_FALSE(map.pass->state().depthTest.has_value());
    EXPECT_FALSE(map.pass->state().blend.has_value());
    EXPECT_FALSE(map.pass->state().depthWrite.has_value());
    glEnable(GL_DEPTH_TEST);
}

TEST_F(ShadowMapTest, MaterialUploadsToTheShadowProgramFloodOnlyUntilTheProgramIsAsked) {
    EXPECT_FALSE(shadows.skinnedProgram(SkinningProduct::parenthesised).hasUniform("baseColor"));
    std::int64_t expectedBefore = gl::debugCounters().expectedErrors;
    ShadowPassOptions flood;
    flood.materialUpload = MaterialUpload::always;
    FrameResult bad = run(0.5, flood);
    EXPECT_GT(bad.stats.glErrors, 0) << "the chapter's flood did not reproduce";
    EXPECT_EQ(gl::debugCounters().expectedErrors - expectedBefore, bad.stats.glErrors);

    FrameResult fixed = run(0.5, {});  // askProgram: any error here fails the fixture
    EXPECT_EQ(fixed.stats.glErrors, 0);
    // The flood does not change the map (the uploads fail, the draws do not).
    EXPECT_EQ(texelsBelow(bad.map, 1.0f), texelsBelow(fixed.map, 1.0f));
}

TEST_F(ShadowMapTest, LightParallelToUpGivesFiniteShadows) {
    for (glm::vec3 dir : {glm::vec3(0, -1, 0), glm::vec3(0, 1, 0)}) {
        for (Light& light : scene.lights) light.direction = dir;
        FrameResult r = run(0.5, {}, true);
        EXPECT_TRUE(allFinite(r.map));
        EXPECT_GT(texelsBelow(r.map, 1.0f), 100);
        ASSERT_TRUE(r.color);
        EXPECT_TRUE(allFinite(*r.color));
    }
}

TEST_F(ShadowMapTest, CastersOutsideTheLightFrustumStayFiniteAndPancake) {
    // A frustum that starts inside the casters: without depth clamping, everything nearer the light
    // than the near plane would be clipped away and cast nothing.
    ShadowBounds bounds = sceneBounds(World(scene, *meshes, 0.5));
    LightView fitted =
        fitLightFrustum(bounds.casters, bounds.everything, scene.lights[0].direction, 15.0f, kMapSize);
    LightView cut = fitted;
    float pushed = 0.5f * (fitted.nearDistance + fitted.farDistance);
    cut.projection = glm::ortho(-fitted.halfWidth, fitted.halfWidth, -fitted.halfWidth, fitted.halfWidth,
                                pushed, fitted.farDistance);
    cut.viewProjection = cut.projection * cut.view;
    cut.nearDistance = pushed;
    FrameResult r = run(0.5, {}, true, cut);
    EXPECT_TRUE(allFinite(r.map));
    EXPECT_GT(texelsBelow(r.map, 1e-6f), 100) << "casters in front of the near plane are flattened onto it";
    ASSERT_TRUE(r.color);
    EXPECT_TRUE(allFinite(*r.color));

    // A frustum that misses everything: an empty map, and a lit, finite scene.
    LightView away = fitted;
    away.view = glm::translate(fitted.view, glm::vec3(1000.0f, 0.0f, 0.0f));
    away.viewProjection = away.projection * away.view;
    FrameResult empty = run(0.5, {}, true, away);
    EXPECT_EQ(texelsBelow(empty.map, 1.0f), 0);
    ASSERT_TRUE(empty.color);
    EXPECT_TRUE(allFinite(*empty.color));
}

TEST_F(ShadowMapTest, TimeFarPastTheClipLengthGivesTheWrappedPose) {
    const AnimationClip* walk = meshes->model(characterIndex(scene))->model().findClip("walk");
    ASSERT_NE(walk, nullptr);
    double duration = double(walk->duration);
    double late = 0.25 + duration * 1e6;  // about 10 days of walking at a 1 s clip
    FrameResult early = run(0.25, {});
    FrameResult far = run(late, {});
    EXPECT_TRUE(allFinite(far.map));
    int different = 0;
    for (std::size_t i = 0; i < early.map.texels.size(); ++i)
        different += std::abs(early.map.texels[i] - far.map.texels[i]) > 1e-4f;
    EXPECT_LE(different, 50) << "the pose far past the clip's end is not the wrapped one";
    EXPECT_GT(fractionCovered(far.map, far.light, cpuCharacterVertices(late)), 0.99);
}

TEST_F(ShadowMapTest, JointWeightsSummingToZeroOrNotToOneStayFiniteAndRenormalise) {
    // A quad of four vertices drawn straight with the skinned shadow program: joint 0 lifts by 1 m.
    MeshData quad;
    quad.positions = {{-0.5f, 0, -0.5f}, {0.5f, 0, -0.5f}, {0.5f, 0, 0.5f}, {-0.5f, 0, 0.5f}};
    quad.normals.assign(4, glm::vec3(0, 1, 0));
    quad.uvs.assign(4, glm::vec2(0));
    quad.indices = {0, 1, 2, 0, 2, 3};
    auto drawQuad = [&](glm::vec4 weights) {
        std::vector<JointInfluence> influences(4);
        for (auto& i : influences) i.weights = weights;
        SkinnedMesh mesh(quad, influences, "test quad");
        JointMatrixBuffer joints("test joints");
        glm::mat4 lift = glm::translate(glm::mat4(1.0f), glm::vec3(0, 1, 0));
        std::vector<glm::mat4> palette{lift, lift};
        joints.upload(palette);
        joints.bind();
        gl::Texture depth = gl::Texture::create2D(TextureFormat::Depth32F, 16, 16, 1, "test depth");
        gl::FramebufferName fbo = gl::createFramebuffer("test shadow fbo");
        glNamedFramebufferTexture(fbo.name(), GL_DEPTH_ATTACHMENT, depth.name(), 0);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.name());
        glViewport(0, 0, 16, 16);
        glEnable(GL_DEPTH_TEST);
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LESS);
        glDisable(GL_CULL_FACE);
        glClearDepth(1.0);
        glClear(GL_DEPTH_BUFFER_BIT);
        // Looking straight down at the quad from 5 m above, depth range 0..10 m.
        LightView light = fitLightFrustum(Bounds{{-1, -4, -1}, {1, 6, 1}}, {0, -1, 0}, 0.0f, 16);
        GLuint program = shadows.skinnedProgram(SkinningProduct::parenthesised).name();
        glm::mat4 identity(1.0f);
        glProgramUniformMatrix4fv(program, glsl::kModelLocation, 1, GL_FALSE, glm::value_ptr(identity));
        glProgramUniformMatrix4fv(program, glsl::kViewProjectionLocation, 1, GL_FALSE,
                                  glm::value_ptr(light.viewProjection));
        glUseProgram(program);
        mesh.drawSource();
        glFinish();
        FloatImage read = gl::readTexture(depth);
        glBindFramebuffer(GL_FRAMEBUFFER, context().presentFramebuffer());
        glBindVertexArray(0);
        glUseProgram(0);
        float centre = read.texels[std::size_t(8 * 16 + 8)];
        glm::vec4 expected = light.viewProjection * glm::vec4(0, weights == glm::vec4(0) ? 0.0f : 1.0f, 0, 1);
        return std::make_pair(centre, expected.z * 0.5f + 0.5f);
    };
    // Sums to 0: the bind pose, not a collapse to the origin with w = 0.
    auto [zeroDepth, zeroExpected] = drawQuad(glm::vec4(0));
    EXPECT_TRUE(std::isfinite(zeroDepth));
    EXPECT_NEAR(zeroDepth, zeroExpected, 1e-4f);
    // Sums to 0.8 (and to 2): renormalised, the full lift, not 0.8 or 2 of it.
    for (glm::vec4 w : {glm::vec4(0.5f, 0.3f, 0, 0), glm::vec4(1.0f, 1.0f, 0, 0)}) {
        auto [depth, expected] = drawQuad(w);
        EXPECT_TRUE(std::isfinite(depth));
        EXPECT_NEAR(depth, expected, 1e-4f) << w.x << " + " << w.y;
    }
}
