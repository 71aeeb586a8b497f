// The overlay headless (--overlay): it draws into the capture, leaves GL as it found it, keeps alive
// only what the inspector shows, lists culled textures with their reason, and runs the knob sweep
// outside its own frame. One test also renders the picture docs/ shows (FXLAB_UPDATE_DOCS=1 writes
// it into docs/images/).
#include <cstdlib>
#include <filesystem>
#include <memory>

#include <imgui.h>

#include "base/paths.hpp"
#include "image/png_file.hpp"
#include "render_gl/gl_state.hpp"
#include "test_ui_harness.hpp"
#include "ui/inspector_list.hpp"
#include "ui/pass_table.hpp"

using namespace fx;
using namespace fx::test;
namespace fs = std::filesystem;

namespace {

// Pictures the tests make go beside the test binary, in the build tree, whatever the working folder.
fs::path pictureFolder() {
    return fs::read_symlink("/proc/self/exe").parent_path() / "ui-docs";
}

// The share of texels in a rectangle (x0, y0 from the top left) that differ by more than 24 levels.
double differingShare(const ByteImage& a, const ByteImage& b, int x0, int y0, int x1, int y1) {
    int differing = 0, total = 0;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            int row = a.height - 1 - y;
            int d = 0;
            for (int c = 0; c < 3; ++c)
                d = std::max(d, std::abs(int(a.texel(x, row, c)) - int(b.texel(x, row, c))));
            differing += d > 24 ? 1 : 0;
            ++total;
        }
    }
    return total ? double(differing) / total : 0.0;
}

OverlayModel lessonLikeModel(int* step) {
    OverlayModel m;
    m.title = "Test scene: a mip chain";
    m.steps = {
        {"A mip chain", "The sky is drawn into scene.hdr; its mips are built by a pass of their own."}};
    m.step = step;
    m.renderer = "test";
    m.cameraNear = 0.1f;
    m.cameraFar = 50.0f;
    return m;
}

}  // namespace

class UiOverlay : public GlTest {};

TEST_F(UiOverlay, HeadlessOverlayDrawsIntoTheCapture) {
    UiHarness h(640, 360);
    ASSERT_TRUE(h.overlay.ok());
    TestScene scene;
    auto build = [&](FrameGraph& g) { scene.declare(g); };
    int step = 0;
    ByteImage without = h.frame(build, lessonLikeModel(&step), false);
    ByteImage with = h.frame(build, lessonLikeModel(&step), true);
    // The lesson window sits at the top left; the scene beyond the windows is untouched.
    EXPECT_GT(differingShare(without, with, 10, 30, 300, 120), 0.5);
    EXPECT_LT(differingShare(without, with, 620, 300, 640, 360), 0.01);
}

TEST_F(UiOverlay, LeavesGlStateAsItFoundIt) {
    UiHarness h(320, 240);
    TestScene scene;
    h.overlay.inspector().setOpen(true);
    h.overlay.inspector().select("scene.hdr");
    int step = 0;
    h.frame([&](FrameGraph& g) { scene.declare(g); }, lessonLikeModel(&step));  // selected from now on

    // A frame by hand, with unusual state bound when the overlay starts drawing.
    FrameGraph graph(OutputTarget{{320, 240}, "output", TextureFormat::RGBA8, 0});
    scene.declare(graph);
    for (auto& name : h.overlay.wantedTextures()) graph.inspect(name);
    ASSERT_TRUE(graph.execute(h.pool, h.executor).ok());
    glBindFramebuffer(GL_FRAMEBUFFER, h.outputFramebuffer());
    glViewport(3, 4, 200, 100);
    glEnable(GL_DEPTH_TEST);
    glUseProgram(scene.program.name());
    GlStateSnapshot before = snapshotGlState();
    GLint fboBefore = 0, fboAfter = 0, programBefore = 0, programAfter = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fboBefore);
    glGetIntegerv(GL_CURRENT_PROGRAM, &programBefore);

    OverlayModel m = lessonLikeModel(&step);
    FrameReport report = graph.report();
    m.frame = &report;
    m.graph = &graph;
    h.overlay.draw(m, 320, 240, 1.0 / 60.0);

    GlStateSnapshot after = snapshotGlState();
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fboAfter);
    glGetIntegerv(GL_CURRENT_PROGRAM, &programAfter);
    EXPECT_EQ(fboAfter, fboBefore);
    EXPECT_EQ(programAfter, programBefore);
    EXPECT_TRUE(after == before) << "the overlay changed the GL state the next pass inherits";
    // And it did draw the chain: 320x240 has 9 levels.
    EXPECT_EQ(h.overlay.inspector().strip().tiles().size(), 9u);
    graph.releaseTextures();
    h.pool.endFrame();
    glDisable(GL_DEPTH_TEST);
    glUseProgram(0);
}

TEST_F(UiOverlay, KeepsAliveOnlyWhatTheOpenInspectorShows) {
    UiHarness h(160, 90);
    TestScene scene;
    int step = 0;
    auto build = [&](FrameGraph& g) {
        scene.declare(g);
        // Nobody reads this one: culled, unless the inspector shows it.
        g.addPass("debug view", [](PassContext&) {})
            .create("debug.normals", {TextureSize::output(), TextureFormat::RGBA8, 1},
                    TextureUsage::ColorAttachment);
    };
    h.overlay.inspector().select("debug.normals");
    h.frame(build, lessonLikeModel(&step));
    EXPECT_TRUE(h.overlay.wantedTextures().empty())
        << "the inspector is collapsed: it must not change the frame";
    const PassRecord* debug = h.report.findPass("debug view");
    ASSERT_NE(debug, nullptr);
    EXPECT_FALSE(debug->executed);

    // Listed, greyed, with the reason.
    auto entries = listTextures(h.report);
    auto it = std::find_if(entries.begin(), entries.end(),
                           [](auto& e) { return e.texture->name == "debug.normals"; });
    ASSERT_NE(it, entries.end());
    EXPECT_FALSE(it->made);
    EXPECT_NE(it->texture->reason.find("output unused"), std::string::npos) << it->texture->reason;

    // Open, with another texture selected: the thumbnails are refreshed in turn, but only from
    // textures the frame makes anyway, so the culled pass stays culled.
    h.overlay.inspector().setOpen(true);
    h.overlay.inspector().select("scene.hdr");
    for (int i = 0; i < 6; ++i) {
        h.frame(build, lessonLikeModel(&step));
        EXPECT_FALSE(h.report.findPass("debug view")->executed) << "frame " << i;
    }
    h.overlay.inspector().select("debug.normals");
    h.frame(build, lessonLikeModel(&step));
    auto wanted = h.overlay.wantedTextures();
    EXPECT_NE(std::find(wanted.begin(), wanted.end(), "debug.normals"), wanted.end());
    h.frame(build, lessonLikeModel(&step));
    EXPECT_TRUE(h.report.findPass("debug view")->executed) << "selecting it brings the pass back";
}

// A sweep whose rows are known: one point per next().
class FakeSweep final : public SweepRun {
public:
    FakeSweep(std::vector<SweepPoint> rows, int* alive) : rows_(std::move(rows)), alive_(alive) {
        ++*alive_;
        r_.lesson = "test";
        r_.width = 960;
        r_.height = 540;
        r_.timingMethod = "glFinish + wall clock";
        r_.copyMs = 1.5;
        r_.frames = 5;
    }
    ~FakeSweep() override { --*alive_; }
    bool done() const override { return r_.points.size() == rows_.size(); }
    void next() override { r_.points.push_back(rows_[r_.points.size()]); }
    SweepProgress progress() const override {
        return {int(r_.points.size()), int(rows_.size()), done() ? "" : rows_[r_.points.size()].value};
    }
    const SweepResult& result() const override { return r_; }

private:
    std::vector<SweepPoint> rows_;
    int* alive_;
    SweepResult r_;
};

std::vector<SweepPoint> fakeRows() {
    std::vector<SweepPoint> rows = {{"taps", "4", false, false, 2.0, 1.3, 0.031, 30.2, 0.2},
                                    {"taps", "8", false, true, 3.1, 2.1, 0.012, 38.4, 0.08},
                                    {"taps", "16", false, false, 5.9, 3.9, 0.004, 47.9, 0.02},
                                    {"taps", "12", false, false, 6.5, 4.3, 0.009, 41.0, 0.05},
                                    {"taps", "32", true, false, 11.2, 75, 0.0, 100.0, 0.0},
                                    {"levels", "4", false, true, 3.0, 2.0, 0.02, 34.0, 0.1},
                                    {"levels", "6", true, false, 4.0, 2.7, 0.0, 100.0, 0.0}};
    for (SweepPoint& p : rows) {
        p.minMultiple = p.copyMultiple * 0.9;
        p.maxMultiple = p.copyMultiple * 1.15;
    }
    return rows;
}

TEST_F(UiOverlay, MeasureRunsTheSweepOneSettingPerFrame) {
    UiHarness h(960, 540);
    TestScene scene;
    int step = 0;
    int calls = 0, alive = 0;
    OverlayModel m = lessonLikeModel(&step);
    m.measureKnobs = [&]() -> std::unique_ptr<SweepRun> {
        ++calls;
        return std::make_unique<FakeSweep>(fakeRows(), &alive);
    };
    auto build = [&](FrameGraph& g) { scene.declare(g); };
    h.overlay.showFramePanel(true, true);
    h.frame(build, m);
    EXPECT_EQ(calls, 0) << "nothing is measured until asked";
    h.overlay.costPanel().requestMeasure();
    h.frame(build, m);
    EXPECT_EQ(calls, 1);
    // One setting per frame: the app keeps drawing, and the panel says how far the sweep is.
    ASSERT_TRUE(h.overlay.costPanel().progress().has_value());
    EXPECT_EQ(h.overlay.costPanel().progress()->done, 1);
    EXPECT_EQ(h.overlay.costPanel().progress()->total, 7);
    EXPECT_TRUE(h.overlay.costPanel().measurePending());
    EXPECT_FALSE(h.overlay.costPanel().result().has_value());
    h.frame(build, m);
    EXPECT_EQ(h.overlay.costPanel().progress()->done, 2);
    // Cancelled: the sweep is dropped (its destructor puts the parameters back), no result appears.
    h.overlay.costPanel().cancel();
    EXPECT_EQ(alive, 0);
    EXPECT_FALSE(h.overlay.costPanel().measurePending());
    h.frame(build, m);
    EXPECT_FALSE(h.overlay.costPanel().result().has_value());

    // Measured to the end: 7 rows, 7 frames.
    h.overlay.costPanel().requestMeasure();
    ByteImage shot;
    for (int i = 0; i < 7; ++i) shot = h.frame(build, m);
    EXPECT_EQ(calls, 2);
    ASSERT_TRUE(h.overlay.costPanel().result().has_value());
    EXPECT_EQ(h.overlay.costPanel().result()->points.size(), 7u);
    EXPECT_FALSE(h.overlay.costPanel().measurePending());
    EXPECT_EQ(alive, 0);
    EXPECT_EQ(sweptKnobs(*h.overlay.costPanel().result()), (std::vector<std::string>{"taps", "levels"}));
    ScatterPlot plot = sweepPlot(*h.overlay.costPanel().result(), "taps");
    ASSERT_EQ(plot.points.size(), 5u);
    EXPECT_TRUE(plot.points[4].isReference);
    EXPECT_TRUE(plot.points[1].isCurrent);
    // In copies, with the spread.
    EXPECT_DOUBLE_EQ(plot.points[0].x, 1.3);
    EXPECT_DOUBLE_EQ(plot.points[0].xLow, 1.3 * 0.9);
    EXPECT_TRUE(writePng(pictureFolder() / "cost-panel.png", shot).ok());
}

// The picture in docs/images: the inspector on a 1600x900 HDR picture with all 11 mip levels in
// the strip and the probe pinned on the edge of the sun.
TEST_F(UiOverlay, DocumentationPictureOfTheMipStrip) {
    UiHarness h(1600, 900);
    TestScene scene;
    int step = 0;
    auto build = [&](FrameGraph& g) {
        scene.declare(g);
        auto& blur = g.addPass("blur (culled)", [](PassContext&) {});
        blur.create("bloom.down[0]", {TextureSize::outputFraction(1, 2), TextureFormat::RGBA16F, 1},
                    TextureUsage::ColorAttachment);
        blur.disable("disabled in step 3");
        g.addPass("debug normals", [](PassContext&) {})
            .create("debug.normals", {TextureSize::output(), TextureFormat::RGBA8, 1},
                    TextureUsage::ColorAttachment);
    };
    OverlayModel m = lessonLikeModel(&step);
    m.steps = {{"Mip chains",
                "scene.hdr is drawn at full size; a pass of its own then builds every mip level. "
                "Select it in the inspector to see the levels side by side."},
               {"Bloom", "The bright parts are blurred down a chain of half-size textures."}};
    float sun = 30.0f, exposure = 0.0f;
    int filter = 1;
    bool showRings = true;
    ParamSet params;
    params.addFloat("sun_intensity", &sun, 1.0f, 100.0f, "How much brighter than white the sun is.");
    params.addFloat("exposure", &exposure, -4.0f, 4.0f, "Exposure in stops before tone mapping.");
    params.addChoice("mip_filter", &filter, {"box", "linear", "kaiser"},
                     "How each level is made from the one above.");
    params.addBool("rings", &showRings, "Draw the coloured rings.");
    m.params = &params;
    m.lessonPanel = [] {
        ImGui::TextWrapped("A test picture: the inspector's documentation is rendered from it.");
    };
    m.timing = "glFinish + wall clock";
    m.renderer = "llvmpipe (EGL surfaceless)";
    Inspector& inspector = h.overlay.inspector();
    inspector.setOpen(true);
    inspector.select("scene.hdr");
    for (int i = 0; i < 6; ++i) h.frame(build, m);  // thumbnails are refreshed two textures a frame
    // The probe on the sun's rim, zoomed in around it on mip 3.
    ViewSettings& s = inspector.settingsFor("scene.hdr", {1600, 900, TextureFormat::RGBA16F, 11});
    s.level = 3;
    s.transform = DisplayTransform::Reinhard;
    inspector.view().setZoom(2.0, 0.78, 0.72);
    inspector.probe().pin({3, 162, 82, {}});
    ByteImage shot = h.frame(build, m);

    EXPECT_EQ(inspector.strip().tiles().size(), 11u);
    EXPECT_EQ(inspector.probeSample().channels, 4);
    EXPECT_EQ(inspector.chainSamples().size(), 11u);
    ASSERT_TRUE(writePng(pictureFolder() / "inspector-mip-strip.png", shot).ok());
    if (const char* update = std::getenv("FXLAB_UPDATE_DOCS"); update && std::string(update) == "1") {
        ASSERT_TRUE(writePng(projectRoot() / "docs" / "images" / "inspector-mip-strip.png", shot).ok());
    }
}
