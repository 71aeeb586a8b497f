// Lesson 03's draw-order bug (Shader effects chapter §3.3) on the real shadow pass: a shadow pass that
// declares no state of its own inherits the depth test, the executor names what it inherited, and
// with the depth test off the map stays at its clear value; the pass that sets its own state draws the
// casters whatever the previous pass left.
#include <algorithm>

#include "base/paths.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/shadow/shadow_map.hpp"
#include "gl/readback.hpp"
#include "gl_test.hpp"
#include "render/frame_graph.hpp"
#include "render_gl/gl_pass_executor.hpp"
#include "render_gl/gl_texture_allocator.hpp"
#include "scene/scene_loader.hpp"

using namespace fx;

namespace {

struct ShadowRun {
    float minDepth = 1.0f;  // the nearest caster in the map; 1 where nothing was drawn
    std::vector<std::string> inherited;
};

class DrawOrder : public GlTest {
protected:
    static void SetUpTestSuite() {
        auto loaded = loadScene(resourceDir() / "scenes/03_fbo_pipeline.json");
        ASSERT_TRUE(loaded.ok()) << loaded.error();
        scene_ = new Scene(std::move(*loaded));
    }
    static void TearDownTestSuite() {
        delete scene_;
        scene_ = nullptr;
    }

    // One frame with only the shadow pass, run after the previous pass left the depth test `depthTestOn`.
    ShadowRun runShadowPass(bool setsItsOwnState, bool depthTestOn) {
        GlTextureAllocator allocator;
        TexturePool pool(allocator);
        PassTimer timer(TimingMode::Off, reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
        GlPassExecutor executor(timer, {0, true});
        SceneMeshes meshes(*scene_);
        ShadowMap shadows;
        EXPECT_TRUE(programsBuilt());

        ShadowSettings settings = shadowCastingLight(*scene_)->shadow;
        settings.mapSize = 256;  // small: the test reads every texel back
        ShadowPassOptions options;
        options.setsItsOwnState = setsItsOwnState;

        FrameGraph graph(OutputTarget{{16, 16}, "output", TextureFormat::RGBA8, 0});
        DeclaredShadowMap map = shadows.declare(graph, World(*scene_, meshes, 0.5), settings, options);
        EXPECT_NE(map.pass, nullptr);
        graph.inspect("shadow.map");  // nothing reads the map in this frame: keep the pass
        ShadowRun run;
        // What the chapter's UI queue leaves behind (or, in the old order, the frame's draw state).
        if (depthTestOn) {
            glEnable(GL_DEPTH_TEST);
        } else {
            glDisable(GL_DEPTH_TEST);
        }
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
        EXPECT_TRUE(graph.execute(pool, executor).ok());
        if (auto handle = graph.findTexture("shadow.map")) {
            const TextureView& view = graph.texture(*handle);
            FloatImage depth = gl::readTexture(view.native, view.spec);
            run.minDepth = *std::min_element(depth.texels.begin(), depth.texels.end());
        }
        if (const PassRecord* pass = graph.report().findPass("shadow map"))
            run.inherited = pass->stateInherited;
        graph.releaseTextures();
        glDisable(GL_DEPTH_TEST);
        return run;
    }

    static Scene* scene_;
};

Scene* DrawOrder::scene_ = nullptr;

bool names(const std::vector<std::string>& list, const std::string& text) {
    return std::find(list.begin(), list.end(), text) != list.end();
}

TEST_F(DrawOrder, ReorderedShadowPassInheritsTheDepthTestOffAndDrawsNothing) {
    ShadowRun run = runShadowPass(/*setsItsOwnState=*/false, /*depthTestOn=*/false);
    EXPECT_TRUE(names(run.inherited, "depth test: off (inherited)"));
    EXPECT_EQ(run.minDepth, 1.0f)
        << "with the depth test off GL writes no depth: the map keeps its clear value";
}

TEST_F(DrawOrder, TheOldOrderWorksByLuckAndTheCheckSaysSo) {
    ShadowRun run = runShadowPass(false, true);
    EXPECT_TRUE(names(run.inherited, "depth test: on (inherited)"));
    EXPECT_LT(run.minDepth, 0.99f);
}

TEST_F(DrawOrder, APassThatSetsItsOwnStateDrawsWhateverCameBefore) {
    for (bool depthTestOn : {false, true}) {
        ShadowRun run = runShadowPass(true, depthTestOn);
        EXPECT_TRUE(run.inherited.empty()) << run.inherited.front();
        EXPECT_LT(run.minDepth, 0.99f) << "depth test left " << (depthTestOn ? "on" : "off");
    }
}

}  // namespace
