// Alpha-cutout shadows (Shader effects chapter, §2): a uniform belongs to one program. Lesson 02's
// "lattice mannequin" is a skinned character in a texture with square holes (alpha 0). Its shadow, read
// back from the map as floats, has the lattice's holes when every shadow program has the cutoff, and
// is solid when only the first (static) program has it, as in the chapter's bug. A static caster in
// the same lattice keeps its holes either way: the static program always had its cutoff.
#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "base/paths.hpp"
#include "effects/shadow/shadow_map.hpp"
#include "gl/readback.hpp"
#include "gl_test.hpp"
#include "render/frame_graph.hpp"
#include "render/texture_pool.hpp"
#include "render_gl/gl_pass_executor.hpp"
#include "render_gl/gl_texture_allocator.hpp"
#include "render_gl/pass_timer.hpp"
#include "scene/scene_loader.hpp"

using namespace fx;

namespace {

constexpr int kMapSize = 256;
constexpr double kSeconds = 0.37;

// Texels where the shadow pass drew something (the map is cleared to 1).
struct Coverage {
    std::size_t drawn = 0;
    std::size_t drawnOnlyInOther = 0;  // drawn in `other` but not here
    std::size_t drawnOnlyHere = 0;     // drawn here but not in `other`
};

Coverage compare(const FloatImage& map, const FloatImage& other) {
    Coverage c;
    for (std::size_t i = 0; i < map.texels.size() && i < other.texels.size(); ++i) {
        bool here = map.texels[i] < 1.0f, there = other.texels[i] < 1.0f;
        c.drawn += here ? 1 : 0;
        c.drawnOnlyInOther += (!here && there) ? 1 : 0;
        c.drawnOnlyHere += (here && !there) ? 1 : 0;
    }
    return c;
}

}  // namespace

class CutoutShadowTest : public GlTest {
protected:
    Scene scene;
    std::optional<SceneMeshes> meshes;
    ShadowMap shadows;

    void SetUp() override {
        GlTest::SetUp();
        SceneLoadOptions options;
        options.assetRoot = resourceDir();
        auto loaded = loadScene(resourceDir() / "scenes/02_skinned_shadows.json", options);
        ASSERT_TRUE(loaded.ok()) << (loaded.ok() ? "" : loaded.error());
        scene = std::move(*loaded);
        ASSERT_TRUE(programsBuilt());
    }
    void TearDown() override {
        meshes.reset();
        GlTest::TearDown();
    }

    const SceneObject* find(const std::string& name) const {
        for (const SceneObject& o : scene.objects)
            if (o.name == name) return &o;
        return nullptr;
    }
    // Keeps only the objects named (the light and the ground stay), then uploads the meshes.
    void keepOnly(const std::vector<std::string>& names) {
        std::erase_if(scene.objects, [&](const SceneObject& o) {
            return o.castsShadows && std::find(names.begin(), names.end(), o.name) == names.end();
        });
        meshes.emplace(scene);
    }

    FloatImage shadowMap(CutoffUniform cutoff) {
        GlTextureAllocator allocator;
        TexturePool pool(allocator);
        PassTimer timer(TimingMode::Off, "");
        GlPassExecutor executor(timer, {context().presentFramebuffer(), true});
        FrameGraph graph(OutputTarget{{64, 64}, "output", TextureFormat::RGBA8, 0});
        ShadowSettings settings;
        settings.casts = true;
        settings.mapSize = kMapSize;
        settings.extent = 15.0f;
        ShadowPassOptions options;
        options.cutoff = cutoff;
        meshes->update(kSeconds);
        DeclaredShadowMap map = shadows.declare(graph, World(scene, *meshes, kSeconds), settings, options);
        EXPECT_NE(map.pass, nullptr);
        if (!map.pass) return {};
        graph.capture(map.map);
        Status status = graph.execute(pool, executor);
        EXPECT_TRUE(status.ok()) << (status.ok() ? "" : status.error());
        const TextureView& view = graph.texture(map.map);
        FloatImage out = gl::readTexture(view.native, view.spec);
        graph.releaseTextures();
        glBindVertexArray(0);
        glUseProgram(0);
        return out;
    }
};

TEST_F(CutoutShadowTest, SkinnedLatticeCastsHolesOnlyWhenEveryProgramHasTheCutoff) {
    ASSERT_NE(find("lattice mannequin"), nullptr) << "lesson 02's scene lost its cut-out caster";
    keepOnly({"lattice mannequin"});
    ASSERT_EQ(meshes->skinnedObjects(), 1u);

    FloatImage bug = shadowMap(CutoffUniform::firstProgramOnly);
    FloatImage fix = shadowMap(CutoffUniform::everyProgram);
    Coverage fixed = compare(fix, bug);
    Coverage buggy = compare(bug, fix);

    // With the bug the mannequin is a solid silhouette; the fix only takes texels away (the holes).
    ASSERT_GT(buggy.drawn, 300u) << "the mannequin is not in the map";
    EXPECT_EQ(fixed.drawnOnlyHere, 0u) << "the cutoff drew texels the solid silhouette does not have";
    // The lattice is 56 % holes; seen through the light's projection, well over a quarter of the
    // silhouette must be gone.
    EXPECT_LT(double(fixed.drawn), 0.75 * double(buggy.drawn))
        << "no holes in the skinned cut-out shadow: " << fixed.drawn << " of " << buggy.drawn
        << " texels still drawn";
    EXPECT_GT(fixed.drawn, buggy.drawn / 10) << "the lattice's bars cast no shadow";
}

TEST_F(CutoutShadowTest, StaticLatticeKeepsItsHolesWithEitherSetting) {
    const SceneObject* mannequin = find("lattice mannequin");
    ASSERT_NE(mannequin, nullptr);
    // The crate in the mannequin's lattice: drawn by the first (static) program.
    for (SceneObject& o : scene.objects)
        if (o.name == "crate") o.material.baseColorTexture = mannequin->material.baseColorTexture;
    keepOnly({"crate"});

    FloatImage bug = shadowMap(CutoffUniform::firstProgramOnly);
    FloatImage fix = shadowMap(CutoffUniform::everyProgram);
    Coverage c = compare(fix, bug);
    EXPECT_GT(c.drawn, 100u);
    EXPECT_EQ(c.drawnOnlyHere + c.drawnOnlyInOther, 0u)
        << "the static program's cutoff depends on the toggle";

    // Against the crate's own opaque shadow, the lattice crate has holes.
    for (SceneObject& o : scene.objects)
        if (o.name == "crate") o.material.baseColorTexture = {};
    meshes.emplace(scene);
    FloatImage solid = shadowMap(CutoffUniform::everyProgram);
    Coverage holes = compare(fix, solid);
    EXPECT_EQ(holes.drawnOnlyHere, 0u);
    EXPECT_LT(double(holes.drawn), 0.75 * double(compare(solid, fix).drawn))
        << "no holes in the static lattice";
}
