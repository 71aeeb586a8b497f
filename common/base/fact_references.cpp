#include "base/fact_references.hpp"

#include <cctype>

namespace fx {
namespace {

constexpr std::string_view kOpen = "{fact:";

bool isNameCharacter(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
}

// The reference at text[at] (which starts with "{fact:"), and where it ends; nothing when it is not
// one ("{fact:" with no name, or no "}" before the line ends).
std::optional<FactReference> referenceAt(std::string_view text, std::size_t at, std::size_t& end) {
    std::size_t i = at + kOpen.size();
    FactReference r;
    while (i < text.size() && isNameCharacter(text[i])) r.name += text[i++];
    if (r.name.empty()) return std::nullopt;
    if (i < text.size() && text[i] == ' ') {
        ++i;
        while (i < text.size() && text[i] != '}' && text[i] != '\n' && text[i] != '{') r.word += text[i++];
        while (!r.word.empty() && r.word.back() == ' ') r.word.pop_back();
        if (r.word.empty()) return std::nullopt;
    }
    if (i >= text.size() || text[i] != '}') return std::nullopt;
    end = i + 1;
    return r;
}

bool isNumberCharacter(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == 'e' || c == '+';
}

}  // namespace

std::vector<FactReference> factReferences(std::string_view text) {
    std::vector<FactReference> out;
    for (std::size_t at = text.find(kOpen); at != std::string_view::npos; at = text.find(kOpen, at + 1)) {
        std::size_t end = 0;
        if (auto r = referenceAt(text, at, end)) out.push_back(std::move(*r));
    }
    return out;
}

std::optional<std::string> resolveFactReference(const FactReference& reference, const FactLookup& facts) {
    const std::optional<std::string> value = facts(reference.name);
    if (!value) return std::nullopt;
    if (reference.word.empty()) return value;
    // The number after the word, where the word stands alone ("sun 300", not "unsung 3").
    for (std::size_t at = value->find(reference.word); at != std::string::npos;
         at = value->find(reference.word, at + 1)) {
        const std::size_t after = at + reference.word.size();
        const bool alone = (at == 0 || !isNameCharacter((*value)[at - 1])) && after < value->size() &&
                           (*value)[after] == ' ';
        if (!alone) continue;
        std::size_t end = after + 1;
        if (end >= value->size() ||
            (!std::isdigit(static_cast<unsigned char>((*value)[end])) && (*value)[end] != '-'))
            continue;
        while (end < value->size() && isNumberCharacter((*value)[end])) ++end;
        while (end > after + 1 && !std::isdigit(static_cast<unsigned char>((*value)[end - 1]))) --end;
        return value->substr(after + 1, end - after - 1);
    }
    return std::nullopt;
}

std::string resolveFactReferences(std::string_view text, const FactLookup& facts) {
    std::string out;
    std::size_t from = 0;
    for (std::size_t at = text.find(kOpen); at != std::string_view::npos; at = text.find(kOpen, at + 1)) {
        std::size_t end = 0;
        const std::optional<FactReference> r = referenceAt(text, at, end);
        if (!r) continue;
        out += text.substr(from, at - from);
        if (auto value = resolveFactReference(*r, facts))
            out += *value;
        else
            out += "[" + r->name + (r->word.empty() ? "" : " " + r->word) + "?]";
        from = end;
        at = end - 1;
    }
    out += text.substr(from);
    return out;
}

}  // namespace fx
