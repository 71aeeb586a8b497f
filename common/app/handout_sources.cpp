#include "app/handout_sources.hpp"
#include "base/message_text.hpp"
#include "base/path_rule.hpp"
#include "base/paths.hpp"

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

std::vector<Part> translatedParts(const std::vector<Part>& english, const std::vector<Part>& translated) {
    std::vector<Part> parts = translated;
    for (std::size_t i = translated.size(); i < english.size(); ++i) {
        parts.push_back(english[i]);
        parts.back().englishOnly = true;
    }
    return parts;
}

TextPictures::TextPictures(fs::path lessonFolder, fs::path handout)
    : lesson_(std::move(lessonFolder)), handout_(std::move(handout)) {}

Status TextPictures::add(const std::string& markdown, const fs::path& source) {
    for (const std::string& target : pictureTargets(markdown)) {
        if (files_.contains(target)) continue;
        if (target.find("://") != std::string::npos)
            return Error{
                cat(source.string(), ": the picture \"", excerpt(target),
                    "\" is not a file of the lesson (a handout holds only the lesson's own pictures)")};
        // The rule for every path a file names (base/path_rule.hpp): a picture of the lesson's text is
        // in the lesson's folder or in docs/, never /etc/passwd copied into the handout's figures.
        const PathRoot roots[] = {{lesson_, "the lesson's folder"}, {projectRoot() / "docs", "docs/"}};
        auto resolved = resolveInsideRoots(target, lesson_, roots, {},
                                           "a lesson's text shows only pictures of the lesson or of docs/");
        if (!resolved) return Error{cat(source.string(), ": the picture ", resolved.error())};
        const fs::path& from = *resolved;
        std::error_code ec;
        if (!fs::exists(from, ec))  // anything else there (a FIFO, a folder) is refused by the read, unread
            return Error{cat(source.string(), ": the picture \"", excerpt(target),
                             "\" is not a file of the lesson (", from.string(), ")")};
        // Two pictures of the same name from different folders keep apart.
        std::string name = from.filename().string();
        for (int n = 2; used_.contains(name); ++n) name = cat(n, "-", from.filename().string());
        used_.insert(name);
        if (auto s = copyPicture(from, handout_ / "figures" / name); !s)
            return Error{cat(source.string(), ": the picture \"", excerpt(target), "\": ", s.error())};
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
