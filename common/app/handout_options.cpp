#include "app/handout_options.hpp"

#include <algorithm>
#include <charconv>

#include "app/lesson_text_files.hpp"
#include "base/log.hpp"
#include "base/utf8_path.hpp"

namespace fx::handout {
namespace {

Result<int> wholeNumber(std::string_view text, int low, int high) {
    int v = 0;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || ptr != text.data() + text.size() || v < low || v > high) return Error{};
    return v;
}

Result<std::vector<std::string>> languages(const std::string& text) {
    std::vector<std::string> list;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t comma = text.find(',', start);
        if (comma == std::string::npos) comma = text.size();
        const std::string language = text.substr(start, comma - start);
        const auto& known = lessonTextLanguages();
        if (std::find(known.begin(), known.end(), language) == known.end())
            return Error{
                cat("--lang: \"", language, "\" is not a language of the lessons' text (en, ja, or en,ja)")};
        if (std::find(list.begin(), list.end(), language) != list.end())
            return Error{cat("--lang: ", language, " is given twice")};
        list.push_back(language);
        start = comma + 1;
    }
    return list;
}

}  // namespace

std::string usage() {
    return "usage: fxlab-handout [--lang en|ja|en,ja] [--out DIR] [--force] [--with-bench] [--bench-dir DIR]\n"
           "                     [--size WxH] [--frames N] LESSON_EXECUTABLE...\n"
           "  --lang L      the pages' language; several (en,ja) share the pictures: the first is index.html,\n"
           "                the others index.<lang>.html (default en)\n"
           "  --out DIR     one lesson: its folder (default out/handouts/NN-name); several: a folder with a\n"
           "                contents page and one folder per lesson (default out/handouts)\n"
           "  --force       replace DIR when it has files in it (otherwise refused)\n"
           "  --with-bench  run the bench for the accuracy plots (slow); without it the handout shows the\n"
           "                results of an earlier ./fxlab bench, if any\n"
           "  --bench-dir D where earlier bench results are: D/NN-name/bench.json (default out/bench)\n"
           "  --size WxH    the pictures' size (default 1280x720)\n"
           "  --frames N    the captured moment: frame N of the headless clock (default 3)\n";
}

Result<CommandLine> parseCommandLine(const std::vector<std::string>& args) {
    CommandLine line;
    std::vector<std::string> seen;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        const bool takesValue =
            a == "--lang" || a == "--out" || a == "--bench-dir" || a == "--size" || a == "--frames";
        if (a.rfind("--", 0) == 0 && a != "--force" && a != "--with-bench" && a != "--help" && !takesValue)
            return Error{cat(a, ": not an option of fxlab-handout (see --help)")};
        if (a.rfind("--", 0) == 0) {
            if (std::find(seen.begin(), seen.end(), a) != seen.end()) return Error{cat(a, ": given twice")};
            seen.push_back(a);
        }
        if (takesValue && i + 1 >= args.size()) return Error{cat(a, ": needs a value")};
        const std::string value = takesValue ? args[++i] : std::string();
        if (a == "--help") {
            line.help = true;
        } else if (a == "--force") {
            line.force = true;
        } else if (a == "--with-bench") {
            line.options.withBench = true;
        } else if (a == "--lang") {
            auto list = languages(value);
            if (!list) return Error{list.error()};
            line.options.languages = *list;
        } else if (a == "--out") {
            if (value.empty()) return Error{"--out: needs a folder"};
            line.out = pathFromUtf8(value);
        } else if (a == "--bench-dir") {
            if (value.empty()) return Error{"--bench-dir: needs a folder"};
            line.options.benchRoot = pathFromUtf8(value);
        } else if (a == "--size") {
            const std::size_t x = value.find('x');
            auto w = wholeNumber(std::string_view(value).substr(0, x), 1, 8192);
            auto h = x == std::string::npos ? Result<int>(Error{})
                                            : wholeNumber(std::string_view(value).substr(x + 1), 1, 8192);
            if (!w || !h)
                return Error{cat("--size: expected WxH with sizes from 1 to 8192, got \"", value, "\"")};
            line.options.size = {*w, *h};
        } else if (a == "--frames") {
            auto n = wholeNumber(value, 1, 1000);
            if (!n)
                return Error{cat("--frames: expected a whole number from 1 to 1000, got \"", value, "\"")};
            line.options.frames = *n;
        } else {
            line.lessons.emplace_back(a);
        }
    }
    if (!line.help && line.lessons.empty()) return Error{"no lesson given (see --help)"};
    for (const auto& lesson : line.lessons) {
        if (auto name = lessonFolderOf(lesson); !name) return Error{name.error()};
    }
    return line;
}

std::filesystem::path defaultOut(const CommandLine& line) {
    const std::filesystem::path root = "out/handouts";
    if (line.lessons.size() != 1) return root;
    auto name = lessonFolderOf(line.lessons.front());
    return name ? root / *name : root;
}

}  // namespace fx::handout
