#include "app/handout_io.hpp"

#include "app/lesson_switch.hpp"
#include "base/file_io.hpp"
#include "base/log.hpp"

namespace fx::handout {

namespace fs = std::filesystem;

Result<json> readJson(const fs::path& file) {
    auto text = readTextFile(file);
    if (!text) return Error{text.error()};
    json j = json::parse(*text, nullptr, false);
    if (j.is_discarded()) return Error{cat(file.string(), ": not valid JSON")};
    return j;
}

const json& member(const json& object, const char* key) {
    static const json none;
    if (!object.is_object()) return none;
    auto it = object.find(key);
    return it == object.end() ? none : *it;
}

std::string sizeText(const json& size) {
    if (!size.is_array() || size.size() != 2 || !size[0].is_number() || !size[1].is_number()) return "?";
    return cat(size[0].get<int>(), "x", size[1].get<int>());
}

std::string logTail(const fs::path& log, int lines) {
    auto text = readTextFile(log);
    if (!text) return "(no log)";
    std::string s = *text;
    while (!s.empty() && s.back() == '\n') s.pop_back();
    std::size_t start = s.size();
    for (int n = 0; n < lines && start > 0; ++n) {
        start = s.rfind('\n', start - 1);
        if (start == std::string::npos) {
            start = 0;
            break;
        }
    }
    return s.substr(start == 0 ? 0 : start + 1);
}

Status runLogged(const fs::path& program, const std::vector<std::string>& args, const fs::path& log,
                 const std::string& what) {
    auto code = runAndWait(program, args, log);
    if (!code) return Error{cat(what, ": ", code.error())};
    if (*code != 0)
        return Error{cat(what, " failed (exit code ", *code, "); the end of its output:\n", logTail(log))};
    return Status::success();
}

Status moveFile(const fs::path& from, const fs::path& to) {
    std::error_code ec;
    fs::rename(from, to, ec);
    if (ec) return Error{cat(from.string(), " -> ", to.string(), ": ", ec.message())};
    return Status::success();
}

Status copyPicture(const fs::path& from, const fs::path& to) {
    auto bytes = readFile(from, file_limits::png);
    if (!bytes) return Error{bytes.error()};
    return writeFileAtomically(to, *bytes);
}

}  // namespace fx::handout
