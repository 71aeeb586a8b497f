#include "gl/shader_source.hpp"

#include <algorithm>
#include <regex>
#include <sstream>

#include "base/file_io.hpp"
#include "base/log.hpp"
#include "base/path_rule.hpp"
#include "base/paths.hpp"
#include "gl/macro_budget.hpp"
#include "gl/shader_substitutes.hpp"

namespace fx::gl {
namespace {

namespace fs = std::filesystem;

// Every file's lines are numbered from its index times this, so a log line still names the right file
// where the compiler reports the source-string number 0 for all of them (Mesa does for an error inside
// an expression of an included file: the line is right, the number is not).
constexpr long kLinesPerFile = 100000;

std::string lineDirective(int line, int index) {
    return cat("#line ", long(index) * kLinesPerFile + line, " ", index, "\n");
}

// Where an #include may lead (see Expander::resolve).
Result<fs::path> allowedInclude(const fs::path& includer, const std::string& name, const fs::path& base,
                                const fs::path& includeRoot) {
    const fs::path exercises = projectRoot() / "exercises";
    const PathRoot allowed[] = {{includer.parent_path(), "the including file's folder"},
                                {includeRoot, "the shaders' folder"},
                                {exercises, "exercises/"}};
    const PathRoot forbidden[] = {{exercises / "solutions", "the exercises' answers"}};
    return resolveInsideRoots(name, base, allowed, forbidden,
                              "a shader includes only files beside it, in shaders/ or in exercises/, never "
                              "an exercise's answers");
}

struct Expander {
    const fs::path& includeRoot;
    const FileReader& reader;
    ExpandedSource out;
    std::vector<fs::path> stack;  // files being expanded, for cycle detection
    MacroBudget macros;           // what the macros of every file expand to

    std::string displayName(const fs::path& file) const {
        std::error_code ec;
        auto relative = fs::relative(file, includeRoot, ec);
        if (!ec && !relative.empty() && *relative.begin() != "..") return relative.generic_string();
        return file.generic_string();
    }

    Result<fs::path> resolve(const fs::path& includer, const std::string& name, int line) {
        for (const fs::path& base : {includer.parent_path(), includeRoot}) {
            fs::path candidate = (base / name).lexically_normal();
            std::error_code ec;
            if (!fs::exists(candidate, ec)) continue;
            // The rule for every path a file names (base/path_rule.hpp): an #include stays beside the
            // including file, in shaders/ or in the exercises' own folder, and never reaches an
            // exercise's answers, so a student's one-line #include of the solution is refused.
            if (auto allowed = allowedInclude(includer, name, base, includeRoot); !allowed)
                return Error{cat(displayName(includer), ":", line, ": #include ", allowed.error())};
            return substitutedShaderFile(candidate);
        }
        return Error{cat(displayName(includer), ":", line, ": cannot find included file \"", name,
                         "\" (looked beside the file and in ", includeRoot.generic_string(), ")")};
    }

    // Appends `file` to the output; returns its source-string number.
    Status expand(const fs::path& file, std::string_view defines, bool isMain) {
        if (std::find(stack.begin(), stack.end(), file) != stack.end()) {
            std::string chain;
            for (auto& f : stack) chain += displayName(f) + " -> ";
            return Error{cat("#include cycle: ", chain, displayName(file))};
        }
        auto text = reader(file);
        if (!text) return Error{text.error()};

        int index = static_cast<int>(out.fileNames.size());
        out.fileNames.push_back(displayName(file));
        out.files.push_back(file);
        stack.push_back(file);
        // An included file counts from its own first line.
        if (!isMain) out.text += lineDirective(1, index);

        static const std::regex includeLine(R"(^\s*#\s*include\s+"([^"]+)\"\s*(//.*)?$)");
        static const std::regex versionLine(R"(^\s*#\s*version\b.*)");
        std::istringstream lines(*text);
        std::string line;
        int number = 0;
        bool sawVersion = false;
        while (std::getline(lines, line)) {
            ++number;
            if (!line.empty() && line.back() == '\r') line.pop_back();
            std::smatch match;
            if (isMain && !sawVersion && std::regex_match(line, versionLine)) {
                sawVersion = true;
                out.text += line + "\n";
                if (!defines.empty()) {
                    out.text += std::string(defines);
                    if (defines.back() != '\n') out.text += "\n";
                }
                out.text += lineDirective(number + 1, index);
                continue;
            }
            if (std::regex_match(line, match, includeLine)) {
                auto target = resolve(file, match[1].str(), number);
                if (!target) return Error{target.error()};
                bool already = std::find(out.files.begin(), out.files.end(), *target) != out.files.end();
                if (already && std::find(stack.begin(), stack.end(), *target) == stack.end()) {
                    out.text += "\n";  // included before: keep the line count
                    continue;
                }
                if (auto status = expand(*target, {}, false); !status) return status;
                out.text += lineDirective(number + 1, index);
                continue;
            }
            macros.line(line, cat(displayName(file), ":", number));
            out.text += line + "\n";
        }
        if (isMain && !sawVersion) {
            return Error{
                cat(displayName(file), ":1: the first directive must be #version (e.g. #version 450 core)")};
        }
        stack.pop_back();
        return Status::success();
    }
};

}  // namespace

Result<ExpandedSource> expandShaderSource(const fs::path& file, const fs::path& includeRoot,
                                          std::string_view defines, const FileReader& reader) {
    FileReader read =
        reader ? reader : FileReader([](const fs::path& p) { return readFile(p, file_limits::shader); });
    Expander expander{includeRoot, read, {}, {}, {}};
    auto status = expander.expand(substitutedShaderFile(file.lexically_normal()), defines, true);
    if (!status) return Error{status.error()};
    if (auto bomb = expander.macros.firstOverBudget()) return Error{*bomb};
    return std::move(expander.out);
}

std::string mapCompilerLog(std::string_view log, const std::vector<std::string>& fileNames) {
    auto nameOf = [&](const std::string& index) -> std::string {
        std::size_t i = std::stoul(index);
        return i < fileNames.size() ? fileNames[i] : cat("<source ", index, ">");
    };
    // "file:line" from the reported number and line: the line's block names the file (kLinesPerFile).
    auto place = [&](const std::string& index, const std::string& line) -> std::string {
        const long number = std::stol(line);
        if (number < kLinesPerFile) return cat(nameOf(index), ":", number);
        return cat(nameOf(std::to_string(number / kLinesPerFile)), ":", number % kLinesPerFile);
    };
    static const std::regex mesa(R"(^(\d+):(\d+)\((\d+)\): )");
    static const std::regex nvidia(R"(^(\d+)\((\d+)\) : )");
    static const std::regex amd(R"(^(ERROR|WARNING): (\d+):(\d+): )");
    std::ostringstream out;
    std::istringstream lines{std::string(log)};
    std::string line;
    while (std::getline(lines, line)) {
        std::smatch m;
        if (std::regex_search(line, m, mesa)) {
            out << place(m[1], m[2]) << ":" << m[3] << ": " << m.suffix() << "\n";
        } else if (std::regex_search(line, m, nvidia)) {
            out << place(m[1], m[2]) << ": " << m.suffix() << "\n";
        } else if (std::regex_search(line, m, amd)) {
            out << place(m[2], m[3]) << ": " << m[1] << ": " << m.suffix() << "\n";
        } else if (!line.empty()) {
            out << line << "\n";
        }
    }
    return out.str();
}

}  // namespace fx::gl
