#include "gl/macro_budget.hpp"

#include <cctype>
#include <cstdint>
#include <functional>
#include <map>

#include "base/log.hpp"

namespace fx::gl {
namespace {

bool identifierStart(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}

bool identifierPart(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

}  // namespace

void MacroBudget::line(std::string_view text, std::string where) {
    std::size_t i = text.find_first_not_of(" \t");
    if (i == std::string_view::npos || text[i] != '#') return;
    i = text.find_first_not_of(" \t", i + 1);
    if (i == std::string_view::npos || text.substr(i, 6) != "define") return;
    i = text.find_first_not_of(" \t", i + 6);
    if (i == std::string_view::npos || !identifierStart(text[i])) return;
    Define d;
    d.where = std::move(where);
    while (i < text.size() && identifierPart(text[i])) d.name += text[i++];
    if (i < text.size() && text[i] == '(') {  // a function-like macro: skip its parameters
        const std::size_t close = text.find(')', i);
        i = close == std::string_view::npos ? text.size() : close + 1;
    }
    while (i < text.size()) {
        const char c = text[i];
        if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') break;  // a comment to the end
        if (identifierStart(c)) {
            std::string word;
            while (i < text.size() && identifierPart(text[i])) word += text[i++];
            d.body.push_back(std::move(word));
        } else {
            if (!std::isspace(static_cast<unsigned char>(c))) d.others += 1;
            ++i;
        }
    }
    defines_.push_back(std::move(d));
}

std::optional<std::string> MacroBudget::firstOverBudget() const {
    std::map<std::string, const Define*> byName;
    for (const Define& d : defines_) byName[d.name] = &d;  // the last definition is the one that counts
    std::map<std::string, double> size;
    std::map<std::string, bool> visiting;
    std::function<double(const std::string&)> sizeOf = [&](const std::string& name) -> double {
        auto known = size.find(name);
        if (known != size.end()) return known->second;
        auto it = byName.find(name);
        if (it == byName.end() || visiting[name]) return 1.0;  // not a macro, or one naming itself
        visiting[name] = true;
        double total = it->second->others;
        for (const std::string& word : it->second->body) {
            total += sizeOf(word);
            if (total > kMaxMacroTokens * 1e6) break;  // far enough: no need to count on to infinity
        }
        visiting[name] = false;
        return size[name] = total;
    };
    for (const Define& d : defines_) {
        const double tokens = sizeOf(d.name);
        if (tokens > kMaxMacroTokens)
            return cat(d.where, ": the macro ", d.name, " expands to ",
                       tokens > 1e15 ? std::string("over 1e15") : std::to_string(std::uint64_t(tokens)),
                       " tokens, past the ", std::uint64_t(kMaxMacroTokens),
                       " a shader may grow to (a macro naming another several times doubles at each level); "
                       "the shader is not compiled");
    }
    return std::nullopt;
}

}  // namespace fx::gl
