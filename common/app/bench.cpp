#include "app/bench.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <nlohmann/json.hpp>

#include "base/file_io.hpp"
#include "base/log.hpp"
#include "gl/program.hpp"
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

// The unit of cost: one full-screen pass that samples a texture and writes the output.
class CopyFrame final : public Lesson {
public:
    LessonInfo info() const override { return {0, "copy", "one full-screen copy", ""}; }
    std::vector<std::string> steps() const override { return {"copy"}; }
    Status init(const Scene&) override {
        copy_ = gl::ReloadableProgram({"common/fullscreen.vert", "common/copy.frag", {}, {}, "bench copy"});
        vao_ = gl::createVertexArray("bench copy triangle");
        return copy_.usable() ? Status::success() : Status(Error{copy_.error()});
    }
    void buildFrame(FrameGraph& graph, const FrameInfo&) override {
        auto& source = graph.addPass("copy source", {});
        TextureHandle texture = source.create(
            "copy.source", {TextureSize::output(), TextureFormat::RGBA16F, 1}, TextureUsage::ColorAttachment);
        source.setState({.clearColor = ClearColor{0.5f, 0.25f, 0.125f, 1.0f}});
        graph
            .addPass("copy",
                     [this, texture](PassContext& ctx) {
                         glBindTextureUnit(0, ctx.native(texture));
                         glUseProgram(copy_.name());
                         glBindVertexArray(vao_.name());
                         glDrawArrays(GL_TRIANGLES, 0, 3);
                     })
            .read(texture)
            .writeColor(graph.output())
            .setState({.depthTest = false, .depthWrite = false, .blend = false, .faceCulling = false});
    }

private:
    gl::ReloadableProgram copy_;
    gl::VertexArrayName vao_;
};

struct Measured {
    double medianMs = 0;
    FloatImage image;
    std::vector<CapturedTexture> effect;
};

Measured measure(Lesson& lesson, FrameRenderer& renderer, const FrameInfo& frame, int frames,
                 const std::string& pass, const std::vector<std::string>& effectTextures) {
    // GPU timer results arrive a few frames late: warm up long enough that they belong to this setting.
    int warmUp = renderer.timer().method() == TimingMethod::GpuTimestamps ? 6 : 2;
    Measured m;
    std::vector<double> times;
    for (int i = 0; i < warmUp + frames; ++i) {
        bool last = i + 1 == warmUp + frames;
        FrameRequest request;
        request.readFinal = last;
        if (last) request.readNamed = effectTextures;
        if (renderer.timer().method() == TimingMethod::GpuTimestamps) glFinish();
        RenderedFrame rendered = renderer.render(lesson, frame, request);
        if (i >= warmUp) {
            double ms = rendered.passMs;
            if (!pass.empty()) {
                const PassRecord* p = rendered.report.findPass(pass);
                ms = p && p->timeMs ? *p->timeMs : 0.0;
            }
            times.push_back(ms);
        }
        if (last) {
            m.image = toFloatImage(rendered.finalImage);
            m.effect = std::move(rendered.textures);
        }
    }
    m.medianMs = median(times);
    return m;
}

// A setting's time, its cost in copies, and its error against the reference: the final image, and
// the lesson's effect texture when both frames captured it.
void fillMeasurement(SweepPoint& point, const Measured& m, const Measured& reference, double copyMs) {
    point.medianMs = m.medianMs;
    point.copyMultiple = copyMs > 0 ? m.medianMs / copyMs : 0;
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

SweepResult sweepKnobs(Lesson& lesson, ParamSet& params, FrameRenderer& renderer, Context& context,
                       const SweepOptions& options, const std::string& lessonName, int step) {
    SweepResult result;
    result.lesson = lessonName;
    Size2D size = context.framebufferSize();
    result.width = size.width;
    result.height = size.height;
    result.timingMethod = std::string(toString(renderer.timer().method()));
    if (size.empty()) return result;

    // A fixed frame: same time, same seed, every setting.
    FrameInfo frame;
    frame.index = 1;
    frame.seconds = 1.0;
    frame.deltaSeconds = 1.0 / 60.0;
    frame.size = {size.width, size.height};
    frame.step = step;
    frame.seed = 1;
    frame.headless = true;
    frame.benchmark = true;
    std::string savedParams = params.toJson();
    const std::vector<ParamSet::Saved> saved = params.save();  // values and where they came from

    {
        CopyFrame copy;  // its GL objects go at the end of this block
        if (copy.init({}))
            result.copyMs = measure(copy, renderer, frame, options.frames, "copy", {}).medianMs;
    }

    result.effectTexture = lesson.benchTexture();
    std::vector<std::string> effect;
    if (!result.effectTexture.empty()) effect.push_back(result.effectTexture);
    setKnobsToReference(params);
    // A separate reference algorithm is rendered with every knob at its reference value too.
    const std::string referenceName = lesson.benchReferenceName();
    const bool separateReference = !referenceName.empty();
    lesson.setBenchReference(separateReference);
    Measured reference = measure(lesson, renderer, frame, options.frames, "", effect);
    lesson.setBenchReference(false);

    auto current = nlohmann::json::parse(savedParams);
    for (const Param* knob : params.knobs()) {
        if (!options.knob.empty() && knob->name != options.knob) continue;
        std::vector<double> values = knob->knob->values;
        // Cut first, then make sure of the reference row: a sweep cut to its first values still has one.
        if (options.maxValues > 0 && int(values.size()) > options.maxValues)
            values.resize(std::size_t(options.maxValues));
        if (!separateReference &&
            std::find(values.begin(), values.end(), knob->knob->reference) == values.end()) {
            values.push_back(knob->knob->reference);
        }
        // Every row, the reference row included, is rendered and timed afresh and compared with the
        // reference image taken above: the reference row's zero error is a measurement (the frame is
        // reproducible), not a copy of the reference's own numbers.
        auto measureRow = [&](std::string value, bool isReference, bool referenceAlgorithm) {
            lesson.setBenchReference(referenceAlgorithm);
            Measured m = measure(lesson, renderer, frame, options.frames, "", effect);
            lesson.setBenchReference(false);
            SweepPoint point;
            point.knob = knob->name;
            point.value = std::move(value);
            point.reference = isReference;
            point.current =
                !referenceAlgorithm && current.contains(knob->name) && current[knob->name] == point.value;
            fillMeasurement(point, m, reference, result.copyMs);
            result.points.push_back(point);
        };
        for (double value : values) {
            setKnobsToReference(params);
            knob->set(value);
            measureRow(knob->valueText(value), !separateReference && value == knob->knob->reference, false);
        }
        if (separateReference) {
            setKnobsToReference(params);
            measureRow(referenceName, true, true);
        }
    }
    params.restore(saved);
    return result;
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

Status writeBenchOutputs(const SweepResult& r, const std::filesystem::path& dir) {
    std::ostringstream csv;
    csv << "lesson,width,height,timing,knob,value,reference,current,median_ms,copy_ms,copy_multiple,rmse,"
           "psnr_db,max_abs,"
           "effect_texture,effect_rmse,effect_psnr_db,effect_max_abs\n";
    nlohmann::ordered_json json;
    json["lesson"] = r.lesson;
    json["size"] = {r.width, r.height};
    json["timingMethod"] = r.timingMethod;
    json["copyMs"] = r.copyMs;
    json["points"] = nlohmann::ordered_json::array();
    for (const SweepPoint& p : r.points) {
        csv << r.lesson << "," << r.width << "," << r.height << "," << r.timingMethod << "," << p.knob
            << ",\"" << p.value << "\"," << p.reference << "," << p.current << "," << number(p.medianMs)
            << "," << number(r.copyMs) << "," << number(p.copyMultiple) << "," << number(p.rmse) << ","
            << number(p.psnr) << "," << number(p.maxAbs) << ",";
        if (p.hasEffectError) {
            csv << r.effectTexture << "," << number(p.effectRmse) << "," << number(p.effectPsnr) << ","
                << number(p.effectMaxAbs);
        } else {
            csv << ",,,";
        }
        csv << "\n";
        json["points"].push_back({{"knob", p.knob},
                                  {"value", p.value},
                                  {"reference", p.reference},
                                  {"current", p.current},
                                  {"medianMs", p.medianMs},
                                  {"copyMultiple", p.copyMultiple},
                                  {"rmse", jsonNumber(p.rmse)},
                                  {"psnrDb", jsonNumber(p.psnr)},
                                  {"maxAbs", jsonNumber(p.maxAbs)}});
        if (p.hasEffectError) {
            json["points"].back()["effect"] = {{"texture", r.effectTexture},
                                               {"rmse", jsonNumber(p.effectRmse)},
                                               {"psnrDb", jsonNumber(p.effectPsnr)},
                                               {"maxAbs", jsonNumber(p.effectMaxAbs)}};
        }
    }
    if (auto s = writeFileAtomically(dir / "bench.csv", csv.str()); !s) return s;
    if (auto s = writeFileAtomically(dir / "bench.json", json.dump(2) + "\n"); !s) return s;

    std::vector<std::string> knobs;
    for (auto& p : r.points) {
        if (std::find(knobs.begin(), knobs.end(), p.knob) == knobs.end()) knobs.push_back(p.knob);
    }
    for (const std::string& knob : knobs) {
        ScatterPlot plot;
        // The title says what was measured and how; the lesson is the folder the plot sits in.
        plot.title = cat(knob, " at ", r.width, "x", r.height, " (", r.timingMethod, ")");
        bool byCopy = r.copyMs > 0;
        plot.xLabel = byCopy
                          ? cat("frame cost in full-screen copies (1 copy = ", shortNumber(r.copyMs), " ms)")
                          : "frame time (ms)";
        plot.yLabel = "RMSE of the final image against the reference";
        for (auto& p : r.points) {
            if (p.knob != knob) continue;
            plot.points.push_back(
                {p.value, byCopy ? p.copyMultiple : p.medianMs, p.rmse, p.reference, p.current});
        }
        if (auto s = writePng(dir / cat("bench-", knob, ".png"), renderScatterPlot(plot)); !s) return s;
    }
    return Status::success();
}

std::string describeSweep(const SweepResult& r) {
    std::ostringstream out;
    out << r.lesson << " at " << r.width << "x" << r.height << ", timing: " << r.timingMethod
        << ", one full-screen copy: " << number(r.copyMs) << " ms\n";
    out << std::left << std::setw(18) << "knob" << std::setw(18) << "value" << std::setw(12) << "ms"
        << std::setw(10) << "x copy" << std::setw(12) << "rmse"
        << "psnr dB\n";
    for (auto& p : r.points) {
        out << std::left << std::setw(18) << p.knob << std::setw(18) << (p.value + (p.reference ? "*" : ""))
            << std::setw(12) << number(p.medianMs) << std::setw(10) << number(p.copyMultiple) << std::setw(12)
            << number(p.rmse) << number(p.psnr) << "\n";
    }
    out << "(* = reference)\n";
    return out.str();
}

}  // namespace fx
