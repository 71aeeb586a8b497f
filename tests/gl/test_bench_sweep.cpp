// The bench's sweep (app/bench.hpp) on a lesson whose picture is known: each knob value fills the
// screen with its own grey. A value that differs from the reference must show an error, every knob
// must have a reference row even when the sweep is cut, and that row must be rendered and measured
// like every other row, not copied from the reference image's own numbers.
#include <map>
#include <utility>

#include "app/bench.hpp"
#include "gl_test.hpp"

using namespace fx;

namespace {

class GreyLesson final : public Lesson {
public:
    explicit GreyLesson(std::string referenceName = {}) : referenceName_(std::move(referenceName)) {}
    std::vector<std::string> steps() const override { return {"grey"}; }
    void declareParams(ParamSet& params) override {
        Param& level = params.addInt("level", &level_, 0, 3, "the grey is level / 4");
        level.knob = Knob{{0, 1, 2}, 3, "level"};
    }
    Status init(const Scene&) override { return Status::success(); }
    void buildFrame(FrameGraph& graph, const FrameInfo& frame) override {
        allBench = allBench && frame.benchmark;
        ++built[{level_, reference_}];
        float grey = reference_ ? 0.9f : float(level_) / 4.0f;
        graph.addPass("fill", {})
            .writeColor(graph.output())
            .setState({.clearColor = ClearColor{grey, grey, grey, 1.0f}});
    }
    std::string benchReferenceName() const override { return referenceName_; }
    void setBenchReference(bool on) override { reference_ = on; }

    // Frames built per (level, reference algorithm).
    int framesBuilt(int level, bool reference) const {
        auto it = built.find({level, reference});
        return it == built.end() ? 0 : it->second;
    }
    std::map<std::pair<int, bool>, int> built;
    bool allBench = true;

private:
    std::string referenceName_;
    int level_ = 1;
    bool reference_ = false;
};

const SweepPoint* row(const SweepResult& r, const std::string& value) {
    for (const SweepPoint& p : r.points)
        if (p.value == value) return &p;
    return nullptr;
}

class BenchSweep : public GlTest {};

TEST_F(BenchSweep, CutSweepKeepsAMeasuredReferenceRowAndShowsErrors) {
    GreyLesson lesson;
    ParamSet params;
    lesson.declareParams(params);
    ASSERT_TRUE(params.assign("level=2").ok());
    FrameRenderer renderer(context(), TimingMode::Fenced, true);
    SweepResult r = sweepKnobs(lesson, params, renderer, context(), {{}, 2, 1, {}}, "grey", 0);

    ASSERT_EQ(r.points.size(), 2u);  // the first value, and the reference added after the cut
    const SweepPoint* first = row(r, "0");
    const SweepPoint* reference = row(r, "3");
    ASSERT_TRUE(first && reference);
    EXPECT_FALSE(first->reference);
    EXPECT_TRUE(reference->reference);
    // Grey 0 against grey 0.75 (sRGB-encoded on the way out): clearly not zero.
    EXPECT_GT(first->rmse, 0.1);
    EXPECT_EQ(reference->rmse, 0.0);
    EXPECT_GT(reference->medianMs, 0.0);
    // The reference setting was rendered twice as often as the other value: once for the image
    // every row is compared with, once for its own row.
    EXPECT_EQ(lesson.framesBuilt(3, false), 2 * lesson.framesBuilt(0, false));
    EXPECT_TRUE(lesson.allBench) << "a sweep frame without FrameInfo::benchmark";
    // The sweep puts the values and their sources back.
    EXPECT_EQ(params.find("level")->text(), "2");
    EXPECT_EQ(params.find("level")->source(), ParamSource::commandLine);
}

TEST_F(BenchSweep, ReferenceAlgorithmRowIsMeasuredNotCopied) {
    GreyLesson lesson("exact");
    ParamSet params;
    lesson.declareParams(params);
    FrameRenderer renderer(context(), TimingMode::Fenced, true);
    SweepResult r = sweepKnobs(lesson, params, renderer, context(), {{}, 2, 0, {}}, "grey", 0);

    ASSERT_EQ(r.points.size(), 4u);  // 0, 1, 2 with the lesson's algorithm, and the reference algorithm
    for (const char* value : {"0", "1", "2"}) {
        const SweepPoint* p = row(r, value);
        ASSERT_TRUE(p) << value;
        EXPECT_FALSE(p->reference) << value;
        EXPECT_GT(p->rmse, 0.01) << value;  // no knob value reaches grey 0.9
    }
    const SweepPoint* exact = row(r, "exact");
    ASSERT_TRUE(exact);
    EXPECT_TRUE(exact->reference);
    EXPECT_EQ(exact->rmse, 0.0);
    EXPECT_GT(exact->medianMs, 0.0);
    // The reference algorithm ran for the reference image and again for its row, as often as a value.
    EXPECT_EQ(lesson.framesBuilt(3, true), 2 * lesson.framesBuilt(0, false));
    EXPECT_EQ(lesson.framesBuilt(3, false), 0);  // the knob's reference value is not a row of its own here
}

// The unit: every row carries the copies timed between its frames, the spread of the per-frame ratios
// around their median, and every pass's time in copies.
TEST_F(BenchSweep, RowsCarryTheirCopyTheSpreadAndEveryPass) {
    GreyLesson lesson;
    ParamSet params;
    lesson.declareParams(params);
    FrameRenderer renderer(context(), TimingMode::Fenced, true);
    std::vector<SweepProgress> seen;
    SweepOptions options{{}, 3, 0, [&](const SweepProgress& p) { seen.push_back(p); }};
    SweepResult r = sweepKnobs(lesson, params, renderer, context(), options, "grey", 0);

    ASSERT_EQ(r.points.size(), 4u);  // 0, 1, 2 and the reference value 3
    EXPECT_EQ(r.frames, 3);
    EXPECT_GT(r.copyMs, 0.0);
    for (const SweepPoint& p : r.points) {
        EXPECT_GT(p.copyMs, 0.0) << p.value;
        EXPECT_GT(p.copyMultiple, 0.0) << p.value;
        EXPECT_LE(p.minMultiple, p.copyMultiple) << p.value;
        EXPECT_GE(p.maxMultiple, p.copyMultiple) << p.value;
        ASSERT_EQ(p.passes.size(), 1u) << p.value;
        EXPECT_EQ(p.passes[0].pass, "fill");
        EXPECT_NEAR(p.passes[0].copies, p.passes[0].medianMs / p.copyMs, 1e-9);
    }
    // Progress before each of the 5 rows (the reference image first), then once at the end.
    ASSERT_EQ(seen.size(), 6u);
    EXPECT_EQ(seen.front().done, 0);
    EXPECT_EQ(seen.front().total, 5);
    EXPECT_EQ(seen[1].next, "level = 0");
    EXPECT_EQ(seen.back().done, 5);
    EXPECT_TRUE(seen.back().next.empty());
}

// The overlay measures a row per frame: between rows the parameters are the user's again, and a
// sweep dropped half-way leaves them as they were.
TEST_F(BenchSweep, SliceAtATimePutsTheParametersBackBetweenSlices) {
    GreyLesson lesson;
    ParamSet params;
    lesson.declareParams(params);
    ASSERT_TRUE(params.assign("level=2").ok());
    FrameRenderer renderer(context(), TimingMode::Fenced, true);
    {
        // One measured frame a setting after two of warm-up (fenced timing): three slices a setting,
        // each one frame of the lesson (and the copy timed before it).
        KnobSweep sweep(lesson, params, renderer, context(), {{}, 1, 0, {}}, "grey", 0);
        EXPECT_EQ(sweep.progress().total, 5);
        for (int slice = 1; slice <= 3; ++slice) {
            sweep.next();  // the reference image, at level 3
            EXPECT_EQ(params.find("level")->text(), "2") << "after slice " << slice;
            EXPECT_EQ(sweep.progress().done, slice == 3 ? 1 : 0);
            EXPECT_EQ(sweep.progress().frame, slice == 3 ? 0 : slice);
        }
        EXPECT_DOUBLE_EQ(sweep.progress().fraction(), 1.0 / 5.0);
        for (int slice = 1; slice <= 3; ++slice) sweep.next();  // level 0
        EXPECT_EQ(params.find("level")->text(), "2");
        EXPECT_EQ(sweep.progress().done, 2);
        EXPECT_FALSE(sweep.done());
        EXPECT_EQ(sweep.result().points.size(), 1u);
        sweep.next();  // a slice of level 1, then dropped: the parameters are put back
    }
    EXPECT_EQ(params.find("level")->text(), "2");
    EXPECT_EQ(params.find("level")->source(), ParamSource::commandLine);
}

// A lesson without knobs has nothing to sweep: no rows, and nothing rendered.
TEST_F(BenchSweep, LessonWithoutKnobsHasNoRows) {
    class NoKnobs final : public Lesson {
    public:
        std::vector<std::string> steps() const override { return {"plain"}; }
        Status init(const Scene&) override { return Status::success(); }
        void buildFrame(FrameGraph& graph, const FrameInfo&) override {
            ++built;
            graph.addPass("fill", {}).writeColor(graph.output());
        }
        int built = 0;
    } lesson;
    ParamSet params;
    FrameRenderer renderer(context(), TimingMode::Fenced, true);
    KnobSweep sweep(lesson, params, renderer, context(), {{}, 2, 0, {}}, "plain", 0);
    EXPECT_TRUE(sweep.done());
    EXPECT_EQ(sweep.progress().total, 0);
    EXPECT_TRUE(sweep.result().points.empty());
    EXPECT_EQ(lesson.built, 0);
    EXPECT_NE(noKnobsMessage("fxlab-04-x").find("no quality knobs"), std::string::npos);
}

}  // namespace
