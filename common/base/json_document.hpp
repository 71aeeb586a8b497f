#pragma once
// The one strict reader for the JSON files a person writes (scenes, parameter presets): a syntax error
// carries the line and column (of the offending token's first character where there is a token); a key
// given twice, a NUL byte, an over-long string, nesting past the limit and a number too large for a
// double are refused by the JSON path of the value ("emitters[0].seed") instead of being read silently
// or stopping the parse blind.
#include <cstddef>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "base/result.hpp"
#include "base/text_position.hpp"

namespace fx {

struct JsonSyntaxError {
    TextPosition at;
    std::string reason;
};

// A value refused by its JSON path. Readers of a document's fields (scene/json_field_reader.hpp) throw
// it too, so one catch turns either into a message.
struct JsonFieldError {
    std::string path;
    std::string reason;
};

[[noreturn]] void failField(std::string path, std::string reason);

std::string fieldPath(std::string_view parent, std::string_view key);  // "camera" + "near" -> "camera.near"
std::string indexPath(std::string_view parent, std::size_t index);     // "lights" + 2 -> "lights[2]"

// "a string", "an array", "null": how a value's type reads in a message.
std::string describeJsonType(const nlohmann::json& value);

// What a kind of document may hold; `document` names it in messages ("scene", "preset").
struct JsonLimits {
    std::string_view document;
    std::size_t maxStringBytes;  // any string, field names included
    std::size_t maxNesting;      // objects and arrays inside one another
};

// Throws JsonSyntaxError or JsonFieldError.
nlohmann::json parseJsonDocument(std::string_view text, const JsonLimits& limits);

// The same, as a Result whose error reads "<file>:<line>:<column>: JSON syntax error: <reason>" or
// "<file>: <path>: <reason>".
Result<nlohmann::json> readJsonDocument(std::string_view text, std::string_view fileName,
                                        const JsonLimits& limits);
// The message of either error, as readJsonDocument words it.
std::string describeJsonError(std::string_view fileName, const JsonSyntaxError& error);
std::string describeJsonError(std::string_view fileName, const JsonFieldError& error);

}  // namespace fx
