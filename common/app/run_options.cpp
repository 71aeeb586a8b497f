#include "app/run_options.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>

#include "base/log.hpp"

namespace fx {
namespace {

constexpr int kMaxSize = 16384;

Result<long> parseWhole(std::string_view text, long min, long max, std::string_view flag, std::string_view what) {
    long value = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || value < min || value > max) {
        return Error{cat(flag, ": expected ", what, " from ", min, " to ", max, ", got \"", text, "\"")};
    }
    return value;
}

}  // namespace

Result<RunOptions> parseRunOptions(const std::vector<std::string>& args) {
    RunOptions o;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& flag = args[i];
        auto value = [&]() -> Result<std::string> {
            if (i + 1 >= args.size()) return Error{cat(flag, ": needs a value")};
            return args[++i];
        };
        auto withValue = [&](auto&& apply) -> Status {
            auto v = value();
            if (!v) return Error{v.error()};
            return apply(*v);
        };
        Status status;
        if (flag == "--help" || flag == "-h") {
            o.help = true;
        } else if (flag == "--list-steps") {
            o.listSteps = true;
        } else if (flag == "--list-params") {
            o.listParams = true;
        } else if (flag == "--headless") {
            o.forceHeadless = true;
        } else if (flag == "--capture-float") {
            o.captureFloat = true;
        } else if (flag == "--bench") {
            o.bench = true;
        } else if (flag == "--knob" || flag == "--bench-out") {
            status = withValue([&](const std::string& v) -> Status {
                if (v.empty()) return Error{cat(flag, ": needs a value")};
                if (flag == "--knob") o.benchKnob = v;
                else o.benchOut = v;
                return Status::success();
            });
        } else if (flag == "--bench-frames" || flag == "--bench-values") {
            status = withValue([&](const std::string& v) -> Status {
                auto n = parseWhole(v, 1, 1000, flag, flag == "--bench-frames" ? "a frame count" : "a value count");
                if (!n) return Error{n.error()};
                (flag == "--bench-frames" ? o.benchFrames : o.benchValues) = int(*n);
                return Status::success();
            });
        } else if (flag == "--overlay") {
            o.overlayHeadless = true;
        } else if (flag == "--no-overlay") {
            o.overlay = false;
        } else if (flag == "--size") {
            status = withValue([&](const std::string& v) -> Status {
                auto x = v.find('x');
                std::string expected = cat("--size: expected WxH with sizes from 0 to ", kMaxSize, ", got \"", v, "\"");
                if (x == std::string::npos) return Error{expected};
                auto w = parseWhole(std::string_view(v).substr(0, x), 0, kMaxSize, "--size", "a width");
                auto h = parseWhole(std::string_view(v).substr(x + 1), 0, kMaxSize, "--size", "a height");
                if (!w || !h) return Error{expected};
                o.width = int(*w);
                o.height = int(*h);
                return Status::success();
            });
        } else if (flag == "--frames") {
            status = withValue([&](const std::string& v) -> Status {
                auto n = parseWhole(v, 1, 1000000, flag, "a frame count");
                if (!n) return Error{n.error()};
                o.frames = int(*n);
                return Status::success();
            });
        } else if (flag == "--step") {
            status = withValue([&](const std::string& v) -> Status {
                auto n = parseWhole(v, 1, 99, flag, "a step number");
                if (!n) return Error{n.error()};
                o.step = int(*n);
                return Status::success();
            });
        } else if (flag == "--seed") {
            status = withValue([&](const std::string& v) -> Status {
                auto n = parseWhole(v, 0, 4294967295L, flag, "a seed");
                if (!n) return Error{n.error()};
                o.seed = static_cast<std::uint32_t>(*n);
                return Status::success();
            });
        } else if (flag == "--time-step") {
            status = withValue([&](const std::string& v) -> Status {
                char* end = nullptr;
                double s = std::strtod(v.c_str(), &end);
                if (end != v.c_str() + v.size() || !std::isfinite(s) || s <= 0 || s > 10) {
                    return Error{cat("--time-step: expected seconds greater than 0 and at most 10, got \"", v, "\"")};
                }
                o.timeStep = s;
                return Status::success();
            });
        } else if (flag == "--scene" || flag == "--capture" || flag == "--report" || flag == "--preset") {
            status = withValue([&](const std::string& v) -> Status {
                if (v.empty()) return Error{cat(flag, ": needs a path")};
                if (flag == "--scene") o.scene = v;
                if (flag == "--capture") o.captureDir = v;
                if (flag == "--report") o.reportFile = v;
                if (flag == "--preset") o.presetFile = v;
                return Status::success();
            });
        } else if (flag == "--param") {
            status = withValue([&](const std::string& v) -> Status {
                if (v.find('=') == std::string::npos || v.front() == '=') {
                    return Error{cat("--param: expected name=value, got \"", v, "\"")};
                }
                o.params.push_back(v);
                return Status::success();
            });
        } else if (flag == "--inspect") {
            status = withValue([&](const std::string& v) -> Status {
                o.inspect.push_back(v);
                return Status::success();
            });
        } else if (flag == "--timing") {
            status = withValue([&](const std::string& v) -> Status {
                if (v == "gpu") o.timing = TimingMode::Gpu;
                else if (v == "fenced") o.timing = TimingMode::Fenced;
                else if (v == "off") o.timing = TimingMode::Off;
                else if (v == "auto") o.timing = TimingMode::Automatic;
                else return Error{cat("--timing: expected one of gpu, fenced, off, auto; got \"", v, "\"")};
                return Status::success();
            });
        } else if (flag == "--lang") {
            status = withValue([&](const std::string& v) -> Status {
                if (v != "en" && v != "ja") return Error{cat("--lang: expected en or ja, got \"", v, "\"")};
                o.language = v;
                return Status::success();
            });
        } else {
            status = Error{cat("unknown option \"", flag, "\" (see --help)")};
        }
        if (!status) return Error{status.error()};
    }
    return o;
}

std::string runOptionsHelp(const std::string& program) {
    return cat("usage: ", program, R"( [options]

  --headless            render without a window (automatic when there is no display)
  --size WxH            framebuffer size, 0 to 16384 each (0 renders nothing, like a minimised window)
  --frames N            frames to render, then exit (default 3 headless; a window runs until closed)
  --step K              start at step K of the lesson (see --list-steps)
  --scene FILE          a scene file instead of the lesson's default (see docs/scene-format.md)
  --param NAME=VALUE    set a parameter, checked against its type and range (see --list-params)
  --preset FILE         load parameters from a preset file (the overlay saves these)
  --capture DIR         write the final image and every intermediate texture as PNG into DIR
  --capture-float       with --capture: also write exact 32-bit floats (PFM)
  --report FILE         write a JSON report: renderer, frame times, GL errors, texture statistics, passes
  --time-step S         fixed time step in seconds (headless runs always use one; default 1/60)
  --seed N              seed for everything random (default 1)
  --timing MODE         pass timing: gpu (timer queries), fenced (glFinish + wall clock), off, auto
  --inspect NAME        keep a texture (and the passes that make it) alive, as the inspector does
  --overlay             draw the overlay into headless captures too
  --no-overlay          start with the overlay hidden (F1 toggles it)
  --bench               sweep the quality knobs (headless): time and error against the reference,
                        written to out/bench/<lesson>/ (bench.csv, bench.json, bench-<knob>.png)
  --knob NAME           with --bench: only this knob
  --bench-frames N      with --bench: measured frames per setting (default 5; the median is kept)
  --bench-values N      with --bench: only the first N values of each knob
  --bench-out DIR       with --bench: where the results go
  --lang LANG           the language of the lesson's text: en (lesson.md, the default) or ja
                        (lesson.ja.md, English for a step it lacks)
  --list-steps          print the lesson's steps with their text from lesson.md and exit (an error
                        when lesson.md does not match the steps; with --lang ja, lesson.ja.md too)
  --list-params         print the lesson's parameters with their ranges and exit
  --help                this text

keys in a window: left/right arrow = previous/next step, F1 = overlay, F5 = reload shaders,
F12 = screenshot to out/, Esc = quit
)");
}

}  // namespace fx
