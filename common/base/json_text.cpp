#include "base/json_text.hpp"

#include <cstdio>

namespace fx {
namespace {

// The length of the well-formed UTF-8 character at text[i] (RFC 3629: no overlong forms, no
// surrogates, nothing past U+10FFFF), or 0 where there is none.
std::size_t characterLength(std::string_view text, std::size_t i) {
    const auto at = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char b = at(i);
    if (b < 0x80) return 1;
    std::size_t n = 0;
    unsigned char lo = 0x80, hi = 0xBF;  // the allowed range of the second byte
    if (b >= 0xC2 && b <= 0xDF)
        n = 2;
    else if (b == 0xE0)
        n = 3, lo = 0xA0;
    else if (b >= 0xE1 && b <= 0xEC)
        n = 3;
    else if (b == 0xED)
        n = 3, hi = 0x9F;
    else if (b >= 0xEE && b <= 0xEF)
        n = 3;
    else if (b == 0xF0)
        n = 4, lo = 0x90;
    else if (b >= 0xF1 && b <= 0xF3)
        n = 4;
    else if (b == 0xF4)
        n = 4, hi = 0x8F;
    else
        return 0;
    if (i + n > text.size()) return 0;
    if (at(i + 1) < lo || at(i + 1) > hi) return 0;
    for (std::size_t k = 2; k < n; ++k)
        if ((at(i + k) & 0xC0) != 0x80) return 0;
    return n;
}

template <class Json>
Json escaped(const Json& j) {
    if (j.is_string()) {
        const auto& s = j.template get_ref<const std::string&>();
        return isValidUtf8(s) ? j : Json(utf8Escaped(s));
    }
    if (j.is_array()) {
        Json out = Json::array();
        for (const auto& e : j) out.push_back(escaped(e));
        return out;
    }
    if (j.is_object()) {
        Json out = Json::object();
        for (auto it = j.begin(); it != j.end(); ++it) out[utf8Escaped(it.key())] = escaped(it.value());
        return out;
    }
    return j;
}

template <class Json>
std::string dump(const Json& j, int indent) {
    try {
        return j.dump(indent);
    } catch (const nlohmann::json::type_error& e) {
        if (e.id != 316) throw;  // 316: a string that is not UTF-8; anything else is a real fault
    }
    return escaped(j).dump(indent);
}

}  // namespace

bool isValidUtf8(std::string_view text) {
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t n = characterLength(text, i);
        if (n == 0) return false;
        i += n;
    }
    return true;
}

std::string utf8Escaped(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t n = characterLength(text, i);
        if (n == 0) {
            char code[8];
            std::snprintf(code, sizeof code, "\\x%02x", unsigned(static_cast<unsigned char>(text[i])));
            out += code;
            ++i;
            continue;
        }
        out.append(text.substr(i, n));
        i += n;
    }
    return out;
}

std::string dumpJson(const nlohmann::json& j, int indent) {
    return dump(j, indent);
}

std::string dumpJson(const nlohmann::ordered_json& j, int indent) {
    return dump(j, indent);
}

}  // namespace fx
