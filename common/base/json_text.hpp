#pragma once
// JSON as text, for every file and line fxlab writes: names may hold any byte (a scene file or a
// student's folder named in Latin-1, a Windows code page), and nlohmann::json throws type_error.316 on
// a byte that is not UTF-8. dumpJson writes such bytes escaped instead ("sc\xff.json" becomes the JSON
// string "sc\\xff.json", read back as the text `sc\xff.json`), so a report is always written and a
// name is shown as it would be in a message (fx::utf8Escaped), never an abort.
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace fx {

// `text` with every byte that is not part of a well-formed UTF-8 character written as \xNN.
std::string utf8Escaped(std::string_view text);
bool isValidUtf8(std::string_view text);

// j.dump(indent), with any string or key that is not UTF-8 escaped (utf8Escaped) first.
std::string dumpJson(const nlohmann::json& j, int indent = -1);
std::string dumpJson(const nlohmann::ordered_json& j, int indent = -1);

}  // namespace fx
