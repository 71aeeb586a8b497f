#include "app/bench.hpp"
#include "base/json_text.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "base/file_io.hpp"
#include "base/log.hpp"
#include "effects/post/copy_pass.hpp"
#include "image/image_compare.hpp"
#include "image/plot.hpp"
#include "image/png_file.hpp"

namespace fx {
namespace {

double median(std::vector<double> values) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// The unit of cost: one full-screen pass that samples a texture and writes the output. Made while
// the bench runs, with the context current.
class CopyFrame final : public Lesson {
public:
    CopyFrame() { setInfo({0, "copy", "one full-screen copy", ""}); }
    std::vector<std::string> steps() const override { return {"copy"}; }
    bool usable() const { return copy_.reloadable().usable(); }
    void buildFrame(FrameGraph& graph, const FrameInfo&) override {
        auto& source = graph.addPass("copy source", {});
        TextureHandle texture = source.create(
            "copy.source", {TextureSize::output(), TextureFormat::RGBA16F, 1}, TextureUsage::ColorAttachment);
        source.setState({.clearColor = ClearColor{0.5f, 0.25f, 0.125f, 1.0f}}).setTaps(0);  // a clear
        copy_.declare(graph, "copy", texture);
    }

private:
    CopyPass copy_{"bench copy"};
};

struct Measured {
    double medianMs = 0, copyMs = 0;
    double multiple = 0, minMultiple = 0, maxMultiple = 0;  // frame / the copy just before it
    std::vector<PassCost> passes;
    PassTraffic traffic;  // the cost model's, of the last frame (the same every frame of a setting)
    double tapsPerPixel = 0;
    FloatImage image;
    std::vector<CapturedTexture> effect;
};

// The time a frame's report gives one pass (0 when it has none), or the whole frame.
double frameMs(const RenderedFrame& rendered, const std::string& pass) {
    if (pass.empty()) return rendered.passMs;
    const PassRecord* p = rendered.report.findPass(pass);
    return p && p->timeMs ? *p->timeMs : 0.0;
}

// One setting measured a frame at a time: warm-up frames, then `frames` measured frames, each after
// one full-screen copy: copy, setting, copy, setting... A machine whose speed drifts (shared cores,
// clocks) moves both halves of a pair together, so the per-pair ratio is steadier than either time;
// the medians keep the same number of samples on both sides. An app draws its own frames between
// two of these (the picture holds still meanwhile, so the lesson sees the setting's frames in a row).
class SettingMeasure {
public:
    SettingMeasure(bool gpu, int frames)
        : gpu_(gpu), warmUp_(gpu ? 6 : 2), frames_(std::max(frames, 1)) {}  // GPU timer results arrive late

    bool done() const { return next_ >= warmUp_ + frames_; }
    int framesDone() const { return next_; }
    int framesTotal() const { return warmUp_ + frames_; }

    // Renders the next frame of the setting (and the copy before it).
    void next(Lesson& lesson, Lesson* copy, FrameRenderer& renderer, const FrameInfo& frame,
              const std::vector<std::string>& effectTextures) {
        if (done()) return;
        const int i = next_++;
        const bool last = done();
        if (gpu_) glFinish();
        const double copyMs = copy ? frameMs(renderer.render(*copy, frame, {}), "copy") : 0.0;
        FrameRequest request;
        request.readFinal = last;
        if (last) request.readNamed = effectTextures;
        if (gpu_) glFinish();
        RenderedFrame rendered = renderer.render(lesson, frame, request);
        if (i >= warmUp_) {
            const double ms = rendered.passMs;
            times_.push_back(ms);
            copies_.push_back(copyMs);
            if (copyMs > 0) ratios_.push_back(ms / copyMs);  // a copy too fast to time has no ratio
            for (const PassRecord& p : rendered.report.passes) {
                if (!p.timeMs) continue;
                auto [it, fresh] = passTimes_.try_emplace(p.name);
                if (fresh) passOrder_.push_back(p.name);
                it->second.push_back(*p.timeMs);
            }
        }
        if (last) {
            m_.image = toFloatImage(rendered.finalImage);
            m_.effect = std::move(rendered.textures);
            m_.traffic = rendered.report.modelledTraffic();
            m_.tapsPerPixel = rendered.report.tapsPerOutputPixel();
            for (const PassRecord& p : rendered.report.passes) {
                if (p.status == PassStatus::Runs) modelled_[p.name] = {p.traffic.total(), p.taps};
            }
        }
    }

    // Once done: the medians, the ratios' spread and the last frame's pictures.
    Measured result() {
        m_.medianMs = median(times_);
        m_.copyMs = median(copies_);
        if (!ratios_.empty()) {
            m_.multiple = median(ratios_);
            m_.minMultiple = *std::min_element(ratios_.begin(), ratios_.end());
            m_.maxMultiple = *std::max_element(ratios_.begin(), ratios_.end());
        }
        for (const std::string& name : passOrder_) {
            const double ms = median(passTimes_[name]);
            const auto& [traffic, taps] = modelled_[name];
            m_.passes.push_back({name, ms, m_.copyMs > 0 ? ms / m_.copyMs : 0.0, traffic, taps});
        }
        return std::move(m_);
    }

private:
    bool gpu_;
    int warmUp_, frames_;
    int next_ = 0;
    Measured m_;
    std::vector<double> times_, copies_, ratios_;
    std::vector<std::string> passOrder_;
    std::map<std::string, std::vector<double>> passTimes_;
    std::map<std::string, std::pair<std::uint64_t, std::optional<double>>> modelled_;  // traffic, taps
};

// A setting's time, its cost in copies, and its error against the reference: the final image, and
// the lesson's effect texture when both frames captured it.
void fillMeasurement(SweepPoint& point, Measured& m, const Measured& reference) {
    point.medianMs = m.medianMs;
    point.copyMs = m.copyMs;
    point.copyMultiple = m.multiple;
    point.minMultiple = m.minMultiple;
    point.maxMultiple = m.maxMultiple;
    point.passes = std::move(m.passes);
    point.trafficBytes = m.traffic.total();
    point.tapsPerPixel = m.tapsPerPixel;
    if (auto d = compare(m.image, reference.image); d) {
        point.rmse = d->rmse;
        point.psnr = d->psnr;
        point.maxAbs = d->maxAbs;
    }
    if (!reference.effect.empty() && !m.effect.empty()) {
        if (auto d = compare(m.effect.front().pixels, reference.effect.front().pixels); d) {
            point.hasEffectError = true;
            point.effectRmse = d->rmse;
            point.effectPsnr = d->psnr;
            point.effectMaxAbs = d->maxAbs;
        }
    }
}

void setKnobsToReference(const ParamSet& params) {
    for (const Param* p : params.knobs()) p->set(p->knob->reference);
}

}  // namespace

// One row of the sweep: a knob at one value (or the lesson's reference algorithm).
struct KnobSweep::Row {
    const Param* knob = nullptr;
    double value = 0;
    std::string text;
    bool isReference = false;
    bool referenceAlgorithm = false;
};

struct KnobSweep::Impl {
    Lesson& lesson;
    ParamSet& params;
    FrameRenderer& renderer;
    SweepOptions options;
    FrameInfo frame;
    std::vector<ParamSet::Saved> saved;  // values and where they came from, put back after every row
    nlohmann::json current;              // the values in use when the sweep started
    CopyFrame copy;
    bool copyUsable = false;
    std::vector<std::string> effect;
    std::vector<Row> rows;
    std::size_t nextRow = 0;
    bool referenceDone = false;
    Measured reference;
    std::optional<SettingMeasure> underWay;  // the reference image or row nextRow, a frame at a time

    Impl(Lesson& l, ParamSet& p, FrameRenderer& r, SweepOptions o)
        : lesson(l), params(p), renderer(r), options(std::move(o)) {}

    void report(const SweepProgress& progress) const {
        if (options.progress) options.progress(progress);
    }
};

KnobSweep::KnobSweep(Lesson& lesson, ParamSet& params, FrameRenderer& renderer, Context& context,
                     SweepOptions options, std::string lessonName, int step)
    : impl_(std::make_unique<Impl>(lesson, params, renderer, std::move(options))) {
    Impl& s = *impl_;
    result_.lesson = std::move(lessonName);
    Size2D size = s.options.size.empty() ? context.framebufferSize() : s.options.size;
    result_.width = size.width;
    result_.height = size.height;
    result_.timingMethod = std::string(toString(renderer.timer().method()));
    result_.frames = std::max(s.options.frames, 1);
    result_.effectTexture = lesson.benchTexture();
    if (!result_.effectTexture.empty()) s.effect.push_back(result_.effectTexture);

    // A fixed frame: same time, same seed, every setting.
    s.frame.index = 1;
    s.frame.seconds = 1.0;
    s.frame.world = s.renderer.world(s.frame.seconds);
    s.frame.deltaSeconds = 1.0 / 60.0;
    s.frame.size = {size.width, size.height};
    s.frame.step = step;
    s.frame.seed = 1;
    s.frame.headless = true;
    s.frame.benchmark = true;
    s.saved = params.save();
    s.current = nlohmann::json::parse(params.toJson());
    s.copyUsable = s.copy.usable();
    if (size.empty()) {
        s.referenceDone = true;  // nothing to render: no rows
        return;
    }

    const std::string referenceName = lesson.benchReferenceName();
    const bool separateReference = !referenceName.empty();
    for (const Param* knob : params.knobs()) {
        if (!s.options.knob.empty() && knob->name != s.options.knob) continue;
        std::vector<double> values = knob->knob->values;
        // Cut first, then make sure of the reference row: a sweep cut to its first values still has one.
        if (s.options.maxValues > 0 && int(values.size()) > s.options.maxValues)
            values.resize(std::size_t(s.options.maxValues));
        if (!separateReference &&
            std::find(values.begin(), values.end(), knob->knob->reference) == values.end()) {
            values.push_back(knob->knob->reference);
        }
        for (double value : values)
            s.rows.push_back({knob, value, knob->valueText(value),
                              !separateReference && value == knob->knob->reference, false});
        if (separateReference) s.rows.push_back({knob, knob->knob->reference, referenceName, true, true});
    }
    if (s.rows.empty()) s.referenceDone = true;  // no knobs: nothing to compare with either
}

KnobSweep::~KnobSweep() {
    impl_->params.restore(impl_->saved);
    impl_->lesson.setBenchReference(false);
}

bool KnobSweep::done() const {
    return impl_->referenceDone && impl_->nextRow >= impl_->rows.size();
}

SweepProgress KnobSweep::progress() const {
    const Impl& s = *impl_;
    SweepProgress p;
    p.total = int(s.rows.size()) + 1;
    p.done = (s.referenceDone ? 1 : 0) + int(s.nextRow);
    if (s.rows.empty()) p.total = p.done = 0;
    if (!s.referenceDone) {
        p.next = s.lesson.benchReferenceName().empty()
                     ? "the reference image"
                     : "the reference image (" + s.lesson.benchReferenceName() + ")";
    } else if (s.nextRow < s.rows.size()) {
        const Row& r = s.rows[s.nextRow];
        p.next = cat(r.knob->name, " = ", r.text);
    }
    if (s.underWay) {
        p.frame = s.underWay->framesDone();
        p.frames = s.underWay->framesTotal();
    }
    return p;
}

void KnobSweep::next() {
    Impl& s = *impl_;
    if (done()) return;
    const bool gpu = s.renderer.timer().method() == TimingMethod::GpuTimestamps;
    if (!s.underWay) {
        s.report(progress());
        s.underWay.emplace(gpu, result_.frames);
    }
    // The setting for this frame only: frames drawn between two slices show the user's settings. A
    // separate reference algorithm is rendered with every knob at its reference value too.
    setKnobsToReference(s.params);
    const Row* row = s.referenceDone ? &s.rows[s.nextRow] : nullptr;
    if (row && !row->referenceAlgorithm) row->knob->set(row->value);
    s.lesson.setBenchReference(row ? row->referenceAlgorithm : !s.lesson.benchReferenceName().empty());
    s.underWay->next(s.lesson, s.copyUsable ? &s.copy : nullptr, s.renderer, s.frame, s.effect);
    s.lesson.setBenchReference(false);
    s.params.restore(s.saved);
    if (!s.underWay->done()) return;

    Measured m = s.underWay->result();
    s.underWay.reset();
    if (!row) {
        s.reference = std::move(m);
        s.referenceDone = true;
    } else {
        // Every row, the reference row included, is rendered and timed afresh and compared with the
        // reference image taken first: the reference row's zero error is a measurement (the frame is
        // reproducible), not a copy of the reference's own numbers.
        ++s.nextRow;
        SweepPoint point;
        point.knob = row->knob->name;
        point.value = row->text;
        point.reference = row->isReference;
        point.current = !row->referenceAlgorithm && s.current.contains(row->knob->name) &&
                        s.current[row->knob->name] == point.value;
        fillMeasurement(point, m, s.reference);
        result_.points.push_back(std::move(point));
        // The unit of the whole run: the median of every row's copies.
        std::vector<double> copies;
        for (const SweepPoint& p : result_.points) copies.push_back(p.copyMs);
        result_.copyMs = median(copies);
    }
    if (done()) s.report(progress());
}

SweepResult sweepKnobs(Lesson& lesson, ParamSet& params, FrameRenderer& renderer, Context& context,
                       const SweepOptions& options, const std::string& lessonName, int step) {
    KnobSweep sweep(lesson, params, renderer, context, options, lessonName, step);
    while (!sweep.done()) sweep.next();
    return sweep.result();
}

namespace {

std::string number(double v) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    std::ostringstream out;
    out << std::setprecision(6) << v;
    return out.str();
}

std::string shortNumber(double v) {
    std::ostringstream out;
    out << std::setprecision(3) << v;
    return out.str();
}

nlohmann::ordered_json jsonNumber(double v) {
    if (!std::isfinite(v)) return number(v);  // JSON has no infinity: identical images have PSNR "inf"
    return v;
}

}  // namespace

Status writeBenchOutputs(const SweepResult& r, const std::filesystem::path& dir, BenchCost cost) {
    std::ostringstream csv;
    csv << "lesson,width,height,timing,knob,value,reference,current,median_ms,copy_ms,copy_multiple,"
           "min_multiple,max_multiple,frames,rmse,psnr_db,max_abs,"
           "effect_texture,effect_rmse,effect_psnr_db,effect_max_abs,traffic_mb_1080p,taps_per_pixel\n";
    // Where the time goes: every pass of every row, in milliseconds and in copies, beside the modelled
    // traffic at 1920x1080 and the pass's taps.
    std::ostringstream passes;
    passes << "knob,value,pass,median_ms,copies,traffic_mb_1080p,taps\n";
    nlohmann::ordered_json json;
    json["lesson"] = r.lesson;
    json["size"] = {r.width, r.height};
    json["timingMethod"] = r.timingMethod;
    json["copyMs"] = r.copyMs;
    json["frames"] = r.frames;
    json["points"] = nlohmann::ordered_json::array();
    for (const SweepPoint& p : r.points) {
        csv << r.lesson << "," << r.width << "," << r.height << "," << r.timingMethod << "," << p.knob
            << ",\"" << p.value << "\"," << p.reference << "," << p.current << "," << number(p.medianMs)
            << "," << number(p.copyMs) << "," << number(p.copyMultiple) << "," << number(p.minMultiple) << ","
            << number(p.maxMultiple) << "," << r.frames << "," << number(p.rmse) << "," << number(p.psnr)
            << "," << number(p.maxAbs) << ",";
        if (p.hasEffectError) {
            csv << r.effectTexture << "," << number(p.effectRmse) << "," << number(p.effectPsnr) << ","
                << number(p.effectMaxAbs);
        } else {
            csv << ",,,";
        }
        csv << "," << number(double(p.trafficBytes) / 1e6) << "," << number(p.tapsPerPixel) << "\n";
        json["points"].push_back({{"knob", p.knob},
                                  {"value", p.value},
                                  {"reference", p.reference},
                                  {"current", p.current},
                                  {"medianMs", p.medianMs},
                                  {"copyMs", p.copyMs},
                                  {"copyMultiple", p.copyMultiple},
                                  {"minMultiple", p.minMultiple},
                                  {"maxMultiple", p.maxMultiple},
                                  {"rmse", jsonNumber(p.rmse)},
                                  {"psnrDb", jsonNumber(p.psnr)},
                                  {"maxAbs", jsonNumber(p.maxAbs)},
                                  {"trafficBytes1080p", p.trafficBytes},
                                  {"tapsPerPixel", p.tapsPerPixel}});
        if (p.hasEffectError) {
            json["points"].back()["effect"] = {{"texture", r.effectTexture},
                                               {"rmse", jsonNumber(p.effectRmse)},
                                               {"psnrDb", jsonNumber(p.effectPsnr)},
                                               {"maxAbs", jsonNumber(p.effectMaxAbs)}};
        }
        auto& passList = json["points"].back()["passes"] = nlohmann::ordered_json::array();
        for (const PassCost& c : p.passes) {
            passList.push_back(
                {{"pass", c.pass},
                 {"medianMs", c.medianMs},
                 {"copies", c.copies},
                 {"trafficBytes1080p", c.trafficBytes},
                 {"taps", c.taps ? nlohmann::ordered_json(*c.taps) : nlohmann::ordered_json(nullptr)}});
            passes << p.knob << ",\"" << p.value << "\",\"" << c.pass << "\"," << number(c.medianMs) << ","
                   << number(c.copies) << "," << number(double(c.trafficBytes) / 1e6) << ","
                   << (c.taps ? number(*c.taps) : std::string()) << "\n";
        }
    }
    if (auto s = writeFileAtomically(dir / "bench.csv", csv.str()); !s) return s;
    if (auto s = writeFileAtomically(dir / "bench.json", dumpJson(json, 2) + "\n"); !s) return s;
    if (auto s = writeFileAtomically(dir / "passes.csv", passes.str()); !s) return s;

    std::vector<std::string> knobs;
    for (auto& p : r.points) {
        if (std::find(knobs.begin(), knobs.end(), p.knob) == knobs.end()) knobs.push_back(p.knob);
    }
    for (const std::string& knob : knobs) {
        ScatterPlot plot;
        plot.yLabel = "RMSE of the final image against the reference";
        if (cost == BenchCost::traffic) {
            // The model needs no timing: the same numbers on every machine, at every --size.
            plot.title = cat(knob, " at ", r.width, "x", r.height, " (modelled memory traffic)");
            plot.xLabel = "memory traffic a frame at 1920x1080, modelled (MB; docs/bench.md)";
            for (auto& p : r.points) {
                if (p.knob == knob)
                    plot.points.push_back(
                        {p.value, double(p.trafficBytes) / 1e6, p.rmse, p.reference, p.current});
            }
        } else {
            // The title says what was measured and how; the lesson is the folder the plot sits in.
            plot.title = cat(knob, " at ", r.width, "x", r.height, " (", r.timingMethod, ")");
            bool byCopy = r.copyMs > 0;
            plot.xLabel = byCopy ? cat("frame cost in full-screen copies, median and min-max of ", r.frames,
                                       " (1 copy = ", shortNumber(r.copyMs), " ms)")
                                 : "frame time (ms)";
            for (auto& p : r.points) {
                if (p.knob != knob) continue;
                PlotPoint point{p.value, byCopy ? p.copyMultiple : p.medianMs, p.rmse, p.reference,
                                p.current};
                if (byCopy) point.xLow = p.minMultiple, point.xHigh = p.maxMultiple;
                plot.points.push_back(point);
            }
        }
        if (auto s = writePng(dir / cat("bench-", knob, ".png"), renderScatterPlot(plot)); !s) return s;
    }
    return Status::success();
}

std::string describeSweep(const SweepResult& r) {
    std::ostringstream out;
    out << r.lesson << " at " << r.width << "x" << r.height << ", timing: " << r.timingMethod
        << ", one full-screen copy: " << number(r.copyMs) << " ms (median; each frame is divided by a copy"
        << " timed just before it, " << r.frames << " pairs per row)\n";
    out << std::left << std::setw(18) << "knob" << std::setw(18) << "value" << std::setw(12) << "ms"
        << std::setw(10) << "x copy" << std::setw(16) << "min-max" << std::setw(12) << "MB 1080p"
        << std::setw(12) << "rmse"
        << "psnr dB\n";
    for (auto& p : r.points) {
        out << std::left << std::setw(18) << p.knob << std::setw(18) << (p.value + (p.reference ? "*" : ""))
            << std::setw(12) << shortNumber(p.medianMs) << std::setw(10) << shortNumber(p.copyMultiple)
            << std::setw(16) << cat(shortNumber(p.minMultiple), "-", shortNumber(p.maxMultiple))
            << std::setw(12) << shortNumber(double(p.trafficBytes) / 1e6) << std::setw(12) << number(p.rmse)
            << number(p.psnr) << "\n";
    }
    out << "(* = reference; MB 1080p: modelled memory traffic a frame at 1920x1080, docs/bench.md)\n";
    // Where the time goes, for the setting in use (the first row when none is).
    const SweepPoint* shown = nullptr;
    for (const SweepPoint& p : r.points)
        if (p.current && !shown) shown = &p;
    if (!shown && !r.points.empty()) shown = &r.points.front();
    if (shown && !shown->passes.empty()) {
        out << "\npasses of " << shown->knob << " = " << shown->value << " (every row's: passes.csv)\n";
        out << std::left << std::setw(30) << "pass" << std::setw(12) << "ms" << std::setw(10) << "copies"
            << std::setw(12) << "MB 1080p"
            << "taps\n";
        for (const PassCost& c : shown->passes)
            out << std::left << std::setw(30) << c.pass << std::setw(12) << shortNumber(c.medianMs)
                << std::setw(10) << shortNumber(c.copies) << std::setw(12)
                << shortNumber(double(c.trafficBytes) / 1e6)
                << (c.taps ? shortNumber(*c.taps) : std::string("-")) << "\n";
    }
    return out.str();
}

std::string noKnobsMessage(const std::string& lessonName) {
    return cat(lessonName,
               " has no quality knobs: nothing to sweep (docs/bench.md lists the lessons that have some)");
}

}  // namespace fx
