#pragma once
// Parses the text of a scene file into a JSON tree, with errors a person can act on: a syntax error
// carries the line and column (of the offending token's first character where there is a token), and a
// number too large for a double (1e400) is named by its JSON path instead of stopping the parse blind.
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "scene/text_position.hpp"

namespace fx {

struct JsonSyntaxError {
    TextPosition at;
    std::string reason;
};

// Throws JsonSyntaxError, or SceneFieldError (json_field_reader.hpp) for an overflowing number.
nlohmann::json parseJsonDocument(std::string_view text);

}  // namespace fx
