#include "app/handout_sources.hpp"

#include <algorithm>
#include <limits>

#include "app/handout_io.hpp"
#include "base/file_io.hpp"
#include "base/lesson_text.hpp"
#include "base/log.hpp"

namespace fx::handout {

namespace fs = std::filesystem;

Result<LessonText> readLessonText(const fs::path& file) {
    auto text = readTextFile(file);
    if (!text) return Error{text.error()};
    LessonText out;
    bool stepsBegan = false;
    for (const LessonSection& s : parseLessonSections(*text)) {
        if (s.level <= 1) {
            if (s.level == 1 && out.title.empty()) out.title = s.heading;
            out.intro += (out.intro.empty() ? "" : "\n\n") + s.text;
        } else if (isStepSection(s)) {
            stepsBegan = true;
        } else {
            (stepsBegan ? out.after : out.before).push_back({s.heading, s.text, false});
        }
    }
    if (out.title.empty()) return Error{cat(file.string(), ": no \"# \" heading (the lesson's title)")};
    return out;
}

std::string partKey(const std::string& heading) {
    const std::size_t colon = heading.find(':');
    if (colon == std::string::npos || colon == 0) return heading;
    const std::size_t space = heading.rfind(' ', colon);
    const bool numbered =
        space != std::string::npos && space + 1 < colon &&
        std::all_of(heading.begin() + std::ptrdiff_t(space + 1), heading.begin() + std::ptrdiff_t(colon),
                    [](char c) { return c >= '0' && c <= '9'; });
    return numbered ? heading.substr(0, colon) : heading;
}

void replaceOrAdd(std::vector<Part>& parts, const Part& translated) {
    for (Part& p : parts) {
        if (p.englishOnly && partKey(p.heading) == partKey(translated.heading)) {
            p = translated;
            return;
        }
    }
    parts.push_back(translated);
}

TextPictures::TextPictures(fs::path lessonFolder, fs::path handout)
    : lesson_(std::move(lessonFolder)), handout_(std::move(handout)) {}

Status TextPictures::add(const std::string& markdown, const fs::path& source) {
    for (const std::string& target : pictureTargets(markdown)) {
        if (files_.contains(target)) continue;
        const fs::path from = (lesson_ / target).lexically_normal();
        std::error_code ec;
        if (target.find("://") != std::string::npos || !fs::is_regular_file(from, ec))
            return Error{cat(source.string(), ": the picture \"", target, "\" is not a file of the lesson (",
                             from.string(), ")")};
        // Two pictures of the same name from different folders keep apart.
        std::string name = from.filename().string();
        for (int n = 2; used_.contains(name); ++n) name = cat(n, "-", from.filename().string());
        used_.insert(name);
        if (auto s = copyPicture(from, handout_ / "figures" / name); !s) return s;
        files_[target] = "figures/" + name;
    }
    return Status::success();
}

PictureSource TextPictures::source() const {
    return [this](const std::string& target) {
        auto it = files_.find(target);
        return it == files_.end() ? target : it->second;
    };
}

Result<BenchPart> readBench(const fs::path& benchFolder, const fs::path& folder) {
    BenchPart bench;
    bench.applicable = true;
    std::error_code ec;
    if (!fs::is_regular_file(benchFolder / "bench.json", ec)) return bench;
    auto j = readJson(benchFolder / "bench.json");
    if (!j) return Error{j.error()};
    bench.found = true;
    bench.size = sizeText(member(*j, "size"));
    bench.timing = j->value("timingMethod", std::string());
    bench.copyMs = j->value("copyMs", 0.0);
    std::vector<std::string> knobs;
    for (const json& p : member(*j, "points")) {
        const std::string knob = p.value("knob", std::string());
        if (std::find(knobs.begin(), knobs.end(), knob) == knobs.end()) knobs.push_back(knob);
        const json& rmse = member(p, "rmse");  // a string ("inf") where it is not finite
        bench.rows.push_back(
            {knob, p.value("value", std::string()), p.value("reference", false), p.value("current", false),
             bench.copyMs > 0 ? p.value("copyMultiple", 0.0) : p.value("medianMs", 0.0),
             rmse.is_number() ? rmse.get<double>() : std::numeric_limits<double>::infinity()});
    }
    for (const std::string& knob : knobs) {
        const std::string file = cat("bench-", knob, ".png");
        if (!fs::is_regular_file(benchFolder / file, ec)) continue;
        if (auto s = copyPicture(benchFolder / file, folder / file); !s) return Error{s.error()};
        bench.plots.push_back({file, knob, 0, 0});
    }
    return bench;
}

}  // namespace fx::handout
