#include "app/run_options.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <set>
#include <string_view>

#include "app/lesson_text_files.hpp"
#include "app/picture_scale.hpp"
#include "base/log.hpp"
#include "base/message_text.hpp"
#include "base/utf8_path.hpp"
#include "render/frame_report.hpp"
#include "scene/closest_name.hpp"

namespace fx {
namespace {

constexpr int kMaxSize = 16384;

// One use of a flag on the command line: its value (empty for a switch) and what the value is
// checked against.
struct FlagUse {
    std::string_view flag;  // its name, for messages: "--size: expected WxH ..."
    std::string value;
    int stepCount = 0;  // the lesson's, for --step
};

// Checks the value and sets what it stands for; otherwise returns what was wrong, naming the flag.
using Apply = std::function<Status(RunOptions&, const FlagUse&)>;

struct Flag {
    std::string name;         // "--size"
    std::string alias{};      // "-h" for --help; empty for the others
    std::string value{};      // how --help shows the value ("WxH"); empty: a switch, which takes none
    std::string help;         // for --help; each "\n" starts an indented continuation line
    bool repeatable = false;  // each use adds one more (--param, --inspect); others take one value
    Apply apply;
};

// --- What the values may be: the parse and range check of each kind of value ---

Result<std::int64_t> parseWhole(std::string_view text, std::int64_t min, std::int64_t max,
                                std::string_view flag, std::string_view what) {
    std::int64_t value = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || value < min || value > max) {
        return Error{
            cat(flag, ": expected ", what, " from ", min, " to ", max, ", got \"", excerpt(text), "\"")};
    }
    return value;
}

template <class T>
Apply set(T RunOptions::*field, T value) {
    return [field, value](RunOptions& o, const FlagUse&) {
        o.*field = value;
        return Status::success();
    };
}

// A whole number from `min` to `max` (`what` names it: "a frame count"), handed to `store`.
Apply whole(std::int64_t min, std::int64_t max, std::string what,
            std::function<void(RunOptions&, std::int64_t)> store) {
    return [=](RunOptions& o, const FlagUse& use) -> Status {
        auto n = parseWhole(use.value, min, max, use.flag, what);
        if (!n) return Error{n.error()};
        store(o, *n);
        return Status::success();
    };
}

// Any text but an empty one; `noun` says what is expected ("a path").
template <class Field>
Apply nonEmpty(Field RunOptions::*field, std::string noun) {
    return [=](RunOptions& o, const FlagUse& use) -> Status {
        if (use.value.empty()) return Error{cat(use.flag, ": needs ", noun)};
        if constexpr (std::is_same_v<Field, std::filesystem::path>)
            o.*field = pathFromUtf8(use.value);
        else
            o.*field = use.value;
        return Status::success();
    };
}

template <class T>
struct Choice {
    std::string word;
    T value;
};

// One of a few words, each standing for a value.
template <class T>
Apply oneOf(T RunOptions::*field, std::vector<Choice<T>> choices) {
    return [=](RunOptions& o, const FlagUse& use) -> Status {
        std::string words;
        for (const auto& c : choices) {
            if (c.word == use.value) {
                o.*field = c.value;
                return Status::success();
            }
            words += (words.empty() ? "" : ", ") + c.word;
        }
        return Error{cat(use.flag, ": expected one of ", words, "; got \"", excerpt(use.value), "\"")};
    };
}

Status parseSize(RunOptions& o, const FlagUse& use) {
    std::string_view v = use.value;
    auto x = v.find('x');
    Error expected{
        cat(use.flag, ": expected WxH with sizes from 0 to ", kMaxSize, ", got \"", excerpt(v), "\"")};
    if (x == std::string::npos) return expected;
    auto w = parseWhole(v.substr(0, x), 0, kMaxSize, use.flag, "a width");
    auto h = parseWhole(v.substr(x + 1), 0, kMaxSize, use.flag, "a height");
    if (!w || !h) return expected;
    o.width = int(*w);
    o.height = int(*h);
    return Status::success();
}

// The range is the lesson's own: a lesson with five steps takes --step 1 to 5.
Status parseStep(RunOptions& o, const FlagUse& use) {
    if (use.stepCount < 1) return Error{cat(use.flag, ": this lesson has no steps")};
    auto n = parseWhole(use.value, 1, use.stepCount, use.flag, "a step number");
    if (!n) return Error{n.error()};
    o.step = int(*n);
    return Status::success();
}

Status parseTimeStep(RunOptions& o, const FlagUse& use) {
    const std::string& v = use.value;
    char* end = nullptr;
    double s = std::strtod(v.c_str(), &end);
    if (v.empty() || end != v.c_str() + v.size() || !std::isfinite(s) || s <= 0 || s > 10) {
        return Error{
            cat(use.flag, ": expected seconds greater than 0 and at most 10, got \"", excerpt(v), "\"")};
    }
    o.timeStep = s;
    return Status::success();
}

// auto, a percentage (40%) or a share (0.4), from 10% to 100%.
Status parsePictureScale(RunOptions& o, const FlagUse& use) {
    std::string v = use.value;
    if (v == "auto") {
        o.pictureScale.reset();
        return Status::success();
    }
    const bool percent = !v.empty() && v.back() == '%';
    if (percent) v.pop_back();
    char* end = nullptr;
    double s = std::strtod(v.c_str(), &end);
    if (percent) s /= 100.0;
    if (v.empty() || end != v.c_str() + v.size() || !std::isfinite(s) || s < 0.1 || s > 1.0) {
        return Error{cat(use.flag,
                         ": expected auto, or a share of the picture from 0.1 to 1 (or 10% to 100%), got \"",
                         use.value, "\"")};
    }
    o.pictureScale = s;
    return Status::success();
}

// W:H (16:9, 4:3), a ratio (1.85) or free.
Status parseAspect(RunOptions& o, const FlagUse& use) {
    const std::string& v = use.value;
    if (v == "free") {
        o.aspect = 0.0;
        return Status::success();
    }
    Error expected{
        cat(use.flag, ": expected W:H (16:9), a ratio from 0.1 to 10 (1.85) or free, got \"", v, "\"")};
    const auto colon = v.find(':');
    double ratio = 0;
    if (colon != std::string::npos) {
        auto w = parseWhole(std::string_view(v).substr(0, colon), 1, kMaxSize, use.flag, "a width");
        auto h = parseWhole(std::string_view(v).substr(colon + 1), 1, kMaxSize, use.flag, "a height");
        if (!w || !h) return expected;
        ratio = double(*w) / double(*h);
    } else {
        char* end = nullptr;
        ratio = std::strtod(v.c_str(), &end);
        if (v.empty() || end != v.c_str() + v.size()) return expected;
    }
    if (!std::isfinite(ratio) || ratio < 0.1 || ratio > 10) return expected;
    o.aspect = ratio;
    return Status::success();
}

Status addParam(RunOptions& o, const FlagUse& use) {
    // Only the shape here: names, types and ranges are checked once the lesson's parameters are known.
    if (use.value.find('=') == std::string::npos || use.value.front() == '=') {
        return Error{cat(use.flag, ": expected name=value, got \"", excerpt(use.value), "\"")};
    }
    o.params.push_back(use.value);
    return Status::success();
}

Status addInspect(RunOptions& o, const FlagUse& use) {
    // The frame's texture names are known only after its graph is built: see unknownInspectWarnings.
    if (use.value.empty()) return Error{cat(use.flag, ": needs a texture name")};
    o.inspect.push_back(use.value);
    return Status::success();
}

// KEY or KEY@FRAME, KEY one of the window's keys by its --press name.
Status addPress(RunOptions& o, const FlagUse& use) {
    const std::string& v = use.value;
    const auto at = v.find('@');
    const std::string key = v.substr(0, at);
    auto press = keyPressNamed(key);
    if (!press) {
        std::vector<std::string> names;
        for (const WindowKeyHelp& k : windowKeysHelp()) names.push_back(k.token);
        std::string list;
        for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
        auto near = closestName(key, names);
        return Error{cat(use.flag, ": no key named \"", excerpt(key), "\"",
                         near ? cat(" (did you mean ", *near, "?)") : "", "; the keys: ", list)};
    }
    std::int64_t frame = 0;
    if (at != std::string::npos) {
        auto n =
            parseWhole(std::string_view(v).substr(at + 1), 0, 1000000, use.flag, "a frame number after @");
        if (!n) return Error{n.error()};
        frame = *n;
    }
    o.presses.push_back({key, int(frame), *press});
    return Status::success();
}

// WxH@FRAME: sizes as --size takes them.
Status addResize(RunOptions& o, const FlagUse& use) {
    const auto at = use.value.find('@');
    if (at == std::string::npos)
        return Error{cat(use.flag, ": expected WxH@FRAME, got \"", excerpt(use.value), "\"")};
    RunOptions sized;
    if (auto status = parseSize(sized, {use.flag, use.value.substr(0, at), 0}); !status) return status;
    auto frame = parseWhole(std::string_view(use.value).substr(at + 1), 0, 1000000, use.flag,
                            "a frame number after @");
    if (!frame) return Error{frame.error()};
    o.resizes.push_back({*sized.width, *sized.height, int(*frame)});
    return Status::success();
}

// A capture file: RenderDoc's tools open only names ending in .rdc.
Status parseRenderDocFile(RunOptions& o, const FlagUse& use) {
    const std::filesystem::path file = use.value;
    if (use.value.empty() || file.extension() != ".rdc" || file.stem().empty())
        return Error{
            cat(use.flag, ": expected a file name ending in .rdc, got \"", excerpt(use.value), "\"")};
    o.renderdoc = file;
    return Status::success();
}

// The languages lesson text comes in (lesson_text_files.hpp), each its own word.
std::vector<Choice<std::string>> languageChoices() {
    std::vector<Choice<std::string>> choices;
    for (const std::string& language : lessonTextLanguages()) choices.push_back({language, language});
    return choices;
}

// --- Every flag, once: the order here is the order of --help ---

const std::vector<Flag>& flags() {
    static const std::vector<Flag> table = {
        {.name = "--headless",
         .help = "render without a window (automatic when there is no display)",
         .apply = set(&RunOptions::forceHeadless, true)},
        {.name = "--size",
         .value = "WxH",
         .help =
             cat("framebuffer size, 0 to ", kMaxSize, " each (0 renders nothing, like a minimised window)"),
         .apply = parseSize},
        {.name = "--frames",
         .value = "N",
         .help = "frames to render, then exit (default 3 headless; a window runs until closed)",
         .apply =
             whole(1, 1000000, "a frame count", [](RunOptions& o, std::int64_t n) { o.frames = int(n); })},
        {.name = "--step",
         .value = "K",
         .help = "start at step K of the lesson (see --list-steps)",
         .apply = parseStep},
        {.name = "--exercise",
         .value = "N",
         .help =
             "exercise N of this lesson: the student's file stands in for the lesson's, at the exercise's step, checked at every save (docs/exercises.md)",
         .apply =
             whole(1, 99, "an exercise number", [](RunOptions& o, std::int64_t n) { o.exercise = int(n); })},
        {.name = "--scene",
         .value = "FILE",
         .help = "a scene file instead of the lesson's default (see docs/scene-format.md)",
         .apply = nonEmpty(&RunOptions::scene, "a path")},
        {.name = "--lang",
         .value = "en|ja",
         .help = "the language of every word the lesson window shows: en English (default), ja Japanese",
         .apply = oneOf<std::string>(&RunOptions::language, languageChoices())},
        {.name = "--param",
         .value = "NAME=VALUE",
         .help = "set a parameter, checked against its type and range (see --list-params)",
         .repeatable = true,
         .apply = addParam},
        {.name = "--preset",
         .value = "FILE",
         .help = "load parameters from a preset file (the overlay saves these)",
         .apply = nonEmpty(&RunOptions::presetFile, "a path")},
        {.name = "--capture",
         .value = "DIR",
         .help = "write the final image and every intermediate texture as PNG into DIR",
         .apply = nonEmpty(&RunOptions::captureDir, "a path")},
        {.name = "--capture-float",
         .help = "with --capture: also write exact 32-bit floats (PFM)",
         .apply = set(&RunOptions::captureFloat, true)},
        {.name = "--report",
         .value = "FILE",
         .help = "write a JSON report: renderer, frame times, GL errors, texture statistics, passes\n"
                 "(- writes it to standard output)",
         .apply = nonEmpty(&RunOptions::reportFile, "a path")},
        {.name = "--graph",
         .value = "FILE.dot",
         .help = "write the last frame's compiled frame graph as Graphviz dot (- for standard output)",
         .apply = nonEmpty(&RunOptions::graphFile, "a path")},
        {.name = "--dump-shaders",
         .value = "DIR",
         .help = "write every shader the run compiles into DIR as the driver got it (includes and\n"
                 "#defines resolved), named by program label, with DIR/index.tsv",
         .apply = nonEmpty(&RunOptions::shaderDump, "a path")},
        {.name = "--time-step",
         .value = "S",
         .help = "the lesson clock's step in seconds: every frame moves it one step, in a window as\n"
                 "headless, however long the frame takes (default 1/60)",
         .apply = parseTimeStep},
        {.name = "--picture-scale",
         .value = "auto|S",
         .help = cat("in a window (and with --overlay): render the picture at this share of its place\n"
                     "(0.1 to 1, or 10% to 100%) instead of the automatic scale that keeps a frame\n"
                     "within the frame budget (",
                     int(kFrameBudgetMs), " ms); headless without the overlay: always the size asked"),
         .apply = parsePictureScale},
        {.name = "--min-frame-time",
         .value = "MS",
         .help = "in a window: every frame takes at least MS milliseconds (it waits the rest), to see\n"
                 "a lesson as a slow renderer shows it (the lesson clock still moves one step a frame)",
         .apply =
             whole(0, 10000, "milliseconds", [](RunOptions& o, std::int64_t n) { o.minFrameMs = int(n); })},
        {.name = "--aspect",
         .value = "W:H|free",
         .help = "in a window (and with --overlay): the picture's aspect, letterboxed in the space the\n"
                 "panels leave (default 16:9, the aspect the lessons' text assumes); free: the whole space",
         .apply = parseAspect},
        {.name = "--seed",
         .value = "N",
         .help = "seed for everything random (default 1)",
         .apply = whole(0, 4294967295, "a seed",
                        [](RunOptions& o, std::int64_t n) { o.seed = std::uint32_t(n); })},
        {.name = "--timing",
         .value = "MODE",
         .help = "pass timing: gpu (timer queries), fenced (glFinish + wall clock), off, auto",
         .apply = oneOf<TimingMode>(&RunOptions::timing, {{"gpu", TimingMode::Gpu},
                                                          {"fenced", TimingMode::Fenced},
                                                          {"off", TimingMode::Off},
                                                          {"auto", TimingMode::Automatic}})},
        {.name = "--inspect",
         .value = "NAME",
         .help = "keep a texture (and the passes that make it) alive, as the inspector does;\n"
                 "a name the first frame does not have gets a warning with the nearest names",
         .repeatable = true,
         .apply = addInspect},
        {.name = "--overlay",
         .help = "draw the overlay into headless captures too",
         .apply = set(&RunOptions::overlayHeadless, true)},
        {.name = "--no-overlay",
         .help = "start with the overlay hidden (F1 toggles it)",
         .apply = set(&RunOptions::overlay, false)},
        {.name = "--bench",
         .help = "sweep the quality knobs (headless): time and error against the reference,\n"
                 "written to out/bench/<lesson>/ (bench.csv, bench.json, bench-<knob>.png)",
         .apply = set(&RunOptions::bench, true)},
        {.name = "--knob",
         .value = "NAME",
         .help = "with --bench: only this knob",
         .apply = nonEmpty(&RunOptions::benchKnob, "a knob name")},
        {.name = "--bench-frames",
         .value = "N",
         .help = "with --bench: measured frames per setting (default 5; the median is kept)",
         .apply =
             whole(1, 1000, "a frame count", [](RunOptions& o, std::int64_t n) { o.benchFrames = int(n); })},
        {.name = "--bench-values",
         .value = "N",
         .help = "with --bench: only the first N values of each knob",
         .apply =
             whole(1, 1000, "a value count", [](RunOptions& o, std::int64_t n) { o.benchValues = int(n); })},
        {.name = "--bench-out",
         .value = "DIR",
         .help = "with --bench: where the results go (default out/bench/<lesson>/)",
         .apply = nonEmpty(&RunOptions::benchOut, "a path")},
        {.name = "--cost",
         .value = "time|traffic",
         .help = "with --bench: the plots' cost axis: time in full-screen copies (default), or the\n"
                 "memory traffic a frame would move at 1920x1080, modelled (the same on every machine)",
         .apply = oneOf<BenchCost>(&RunOptions::benchCost,
                                   {{"time", BenchCost::time}, {"traffic", BenchCost::traffic}})},
        {.name = "--press",
         .value = "KEY@FRAME",
         .help = "press a window key at frame FRAME (0 when left out), as if typed; KEY is the\n"
                 "name in brackets in the key list below (scripted demonstrations, window tests)",
         .repeatable = true,
         .apply = addPress},
        {.name = "--resize",
         .value = "WxH@FRAME",
         .help =
             "resize the window at frame FRAME, as if its border were dragged (headless: the offscreen target; 0x0 is a minimised window)",
         .repeatable = true,
         .apply = addResize},
        {.name = "--all-steps",
         .help = "with --capture DIR: capture every step of the lesson, each into DIR/step-K/\n"
                 "(with its report.json and graph.dot), one run per step",
         .apply = set(&RunOptions::allSteps, true)},
        {.name = "--resource-log",
         .value = "FILE",
         .help = "every tenth frame, the process's memory and its live GL objects, written as CSV\n"
                 "when the run ends (a soak's figures: tools/soak/run_soak.sh)",
         .apply = nonEmpty(&RunOptions::resourceLog, "a path")},
        {.name = "--renderdoc",
         .value = "FILE.rdc",
         .help = "capture the run's last frame (or --renderdoc-frame N) in RenderDoc, window or headless,\n"
                 "through its in-application API (Debian package renderdoc); in a window F9 captures the\n"
                 "next frame into FILE-2.rdc, FILE-3.rdc ... (docs/debugging.md)",
         .apply = parseRenderDocFile},
        {.name = "--renderdoc-frame",
         .value = "N",
         .help = "with --renderdoc: capture frame N of the run (1 is the first) instead of the last",
         .apply =
             whole(1, 1000000, "a frame number", [](RunOptions& o, long n) { o.renderdocFrame = int(n); })},
        {.name = "--renderdoc-open",
         .help = "with --renderdoc: open each capture in qrenderdoc once written",
         .apply = set(&RunOptions::renderdocOpen, true)},
        {.name = "--list-steps",
         .help = "print the lesson's steps and exit",
         .apply = set(&RunOptions::listSteps, true)},
        {.name = "--list-params",
         .help = "print the lesson's parameters with their ranges and exit",
         .apply = set(&RunOptions::listParams, true)},
        {.name = "--help", .alias = "-h", .help = "this text", .apply = set(&RunOptions::help, true)},
    };
    return table;
}

const Flag* findFlag(std::string_view word) {
    for (const Flag& f : flags()) {
        if (word == f.name || (!f.alias.empty() && word == f.alias)) return &f;
    }
    return nullptr;
}

Error unknownFlag(const std::string& word) {
    std::vector<std::string> names;
    for (const Flag& f : flags()) names.push_back(f.name);
    auto near = closestName(word, names);
    return Error{cat("unknown option \"", excerpt(word), "\"", near ? cat("; did you mean ", *near, "?") : "",
                     " (see --help)")};
}

// "  --size WxH            framebuffer size..." with continuation lines under the text.
std::string helpLine(const std::string& left, const std::string& text) {
    constexpr std::size_t kColumn = 22;
    std::string indent(kColumn + 2, ' ');
    std::string line = "  " + left + std::string(left.size() < kColumn ? kColumn - left.size() : 1, ' ');
    for (char c : text) line += c == '\n' ? "\n" + indent : std::string(1, c);
    return line + "\n";
}

}  // namespace

Result<RunOptions> parseRunOptions(const std::vector<std::string>& args, int stepCount) {
    RunOptions o;
    std::set<std::string> given;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const Flag* flag = findFlag(args[i]);
        if (!flag) return unknownFlag(args[i]);
        std::string value;
        if (!flag->value.empty()) {
            if (i + 1 >= args.size()) return Error{cat(flag->name, ": needs a value (", flag->value, ")")};
            value = args[++i];
            // A second --scene would silently replace the first: say so instead of guessing.
            if (!flag->repeatable && !given.insert(flag->name).second) {
                return Error{cat(flag->name, ": given more than once (again as \"", excerpt(value),
                                 "\"); give it once")};
            }
        }
        if (auto status = flag->apply(o, {flag->name, value, stepCount}); !status)
            return Error{status.error()};
    }
    if (o.allSteps && o.captureDir.empty())
        return Error{"--all-steps: needs --capture DIR (each step's captures go into DIR/step-K/)"};
    if (o.allSteps && o.step) return Error{"--all-steps: captures every step; leave out --step"};
    if (o.renderdoc.empty() && (o.renderdocFrame || o.renderdocOpen))
        return Error{cat(o.renderdocFrame ? "--renderdoc-frame" : "--renderdoc-open",
                         ": needs --renderdoc FILE.rdc (where the capture goes)")};
    if (o.renderdoc.empty() == false && (o.allSteps || o.bench))
        return Error{
            cat("--renderdoc: captures one run's frame; leave out ", o.allSteps ? "--all-steps" : "--bench")};
    if (o.renderdocFrame && o.frames && *o.renderdocFrame > *o.frames)
        return Error{cat("--renderdoc-frame: frame ", *o.renderdocFrame, " of a run of ", *o.frames,
                         " frames (--frames); give a frame from 1 to ", *o.frames)};
    return o;
}

bool runFlagTakesValue(std::string_view word) {
    const Flag* flag = findFlag(word);
    return flag && !flag->value.empty();
}

std::string runOptionsHelp(const std::string& program) {
    std::string text = cat("usage: ", program, " [options]\n\n");
    for (const Flag& f : flags()) {
        std::string left =
            f.name + (f.alias.empty() ? "" : ", " + f.alias) + (f.value.empty() ? "" : " " + f.value);
        text += helpLine(left, f.help);
    }
    text += "\nkeys in a window (the overlay's Keys tab lists the same; [name] for --press):\n";
    for (const WindowKeyHelp& k : windowKeysHelp())
        text += helpLine(cat(k.key, " [", k.token, "]"), k.action);
    return text;
}

std::vector<std::string> unknownInspectWarnings(const std::vector<std::string>& inspect,
                                                const FrameReport& report, int step) {
    std::vector<std::string> known;
    for (const TextureRecord& t : report.textures) known.push_back(t.name);
    std::vector<std::string> warnings;
    for (const std::string& name : inspect) {
        if (std::find(known.begin(), known.end(), name) != known.end()) continue;
        // The nearest few by edit distance; closestName says whether one is near enough to be a typo.
        std::vector<std::string> nearest = known;
        std::stable_sort(nearest.begin(), nearest.end(), [&](const std::string& a, const std::string& b) {
            return editDistance(name, a) < editDistance(name, b);
        });
        if (nearest.size() > 5) nearest.resize(5);
        std::string list;
        for (const auto& n : nearest) list += (list.empty() ? "" : ", ") + n;
        auto typo = closestName(name, known);
        warnings.push_back(
            cat("--inspect: step ", step + 1, "'s frame has no texture named \"", excerpt(name), "\"",
                typo ? cat(" (did you mean \"", *typo, "\"?)") : "",
                known.empty() ? "; it has no textures" : cat("; the nearest names it has: ", list),
                ". Another step may have it (--list-steps)."));
    }
    return warnings;
}

}  // namespace fx
