#include "base/json_document.hpp"

#include <vector>

#include "base/log.hpp"
#include "base/message_text.hpp"

namespace fx {
namespace {

using Json = nlohmann::json;

// "... - unexpected number literal; expected ']'"
bool isUnexpectedLiteral(std::string_view message) {
    auto start = message.find("- unexpected ");
    if (start == std::string_view::npos) return false;
    std::string_view what = message.substr(start);
    what = what.substr(0, what.find(';'));
    return what.ends_with(" literal");
}

// Builds the tree from parser events and knows the JSON path of the value being read, which nlohmann's
// own builder does not: its overflow error has no position at all.
class TreeBuilder : public nlohmann::json_sax<Json> {
public:
    TreeBuilder(std::string_view text, const JsonLimits& limits) : text_(text), limits_(limits) {}

    Json take() { return std::move(root_); }

    bool null() override { return add(nullptr); }
    bool boolean(bool value) override { return add(value); }
    bool number_integer(number_integer_t value) override { return add(value); }
    bool number_unsigned(number_unsigned_t value) override { return add(value); }
    bool number_float(number_float_t value, const string_t&) override { return add(value); }
    bool string(string_t& value) override {
        checkLength(value, "a string");
        return add(std::move(value));
    }
    bool binary(binary_t& value) override { return add(Json::binary(std::move(value))); }

    bool start_object(std::size_t) override { return open(Json::object()); }
    bool key(string_t& key) override {
        checkLength(key, "a field name");
        // nlohmann keeps the last of two equal keys; other JSON readers keep the first. Either way one
        // value is dropped without a word, so a repeated key is an error.
        if (stack_.back().container->contains(key))
            failField(fieldPath(containerPath(), key),
                      "appears twice in the same object; JSON readers disagree on which one counts");
        key_ = std::move(key);
        return true;
    }
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(Json::array()); }
    bool end_array() override { return close(); }

    bool parse_error(std::size_t position, const std::string& lastToken,
                     const nlohmann::detail::exception& error) override {
        std::string_view message = error.what();
        // "[json.exception.parse_error.101] parse error at line 1, column 2: <reason>": keep the reason.
        if (auto colon = message.find(": "); colon != std::string_view::npos)
            message.remove_prefix(colon + 2);
        if (error.id == 406) {  // number overflow: a literal such as 1e400 has no finite double
            failField(
                nextPath(),
                cat("the number ", lastToken,
                    " is not finite (too large for a double: it overflowed; JSON has no infinity or NaN)"));
        }
        // `position` counts the characters read; the last one read is where the lexer stopped. For an
        // unexpected literal (a string, number, true, false or null that is whole but out of place), point
        // at its first character instead; nlohmann's token text is reliable for those.
        std::size_t offset = position > 0 ? position - 1 : 0;
        if (isUnexpectedLiteral(message) && lastToken.find("<U+") == std::string::npos &&
            lastToken.size() <= position)
            offset = position - lastToken.size();
        throw JsonSyntaxError{textPositionOf(text_, offset), std::string(message)};
    }

private:
    struct Open {
        Json* container;
        std::string key;  // its member name, when its parent is an object
    };

    // The JSON path of the innermost open object or array ("" for the top level).
    std::string containerPath() const {
        std::string path;
        for (std::size_t i = 1; i < stack_.size(); ++i) {
            const Json& parent = *stack_[i - 1].container;
            path = parent.is_object() ? fieldPath(path, stack_[i].key) : indexPath(path, parent.size() - 1);
        }
        return path;
    }

    // Where the next value goes: a member of the innermost object, the next element of the innermost
    // array, or the root. Built only for a message, so deep nesting costs no long strings while parsing.
    std::string nextPath() const {
        if (stack_.empty()) return "(top level)";
        const Json& top = *stack_.back().container;
        return top.is_object() ? fieldPath(containerPath(), key_) : indexPath(containerPath(), top.size());
    }

    void checkLength(const std::string& text, std::string_view what) const {
        if (text.size() > limits_.maxStringBytes)
            failField(
                stack_.empty() ? "(top level)" : (what == "a field name" ? containerPath() : nextPath()),
                cat(what, " of ", text.size(), " bytes (\"", excerpt(text), "\"); a ", limits_.document,
                    " allows at most ", limits_.maxStringBytes));
    }

    Json* place(Json value) {
        if (stack_.empty()) {
            root_ = std::move(value);
            return &root_;
        }
        Json& container = *stack_.back().container;
        if (container.is_object()) return &(container[key_] = std::move(value));
        container.push_back(std::move(value));
        return &container.back();
    }

    bool add(Json value) {
        place(std::move(value));
        return true;
    }

    bool open(Json container) {
        if (stack_.size() >= limits_.maxNesting)
            failField(nextPath(), cat("objects and arrays nest more than ", limits_.maxNesting, " deep; a ",
                                      limits_.document, " needs far fewer"));
        bool inObject = !stack_.empty() && stack_.back().container->is_object();
        stack_.push_back({place(std::move(container)), inObject ? key_ : std::string()});
        return true;
    }

    bool close() {
        stack_.pop_back();
        return true;
    }

    std::string_view text_;
    JsonLimits limits_;
    Json root_;
    std::vector<Open> stack_;
    std::string key_;
};

}  // namespace

void failField(std::string path, std::string reason) {
    throw JsonFieldError{std::move(path), std::move(reason)};
}

std::string fieldPath(std::string_view parent, std::string_view key) {
    return parent.empty() ? std::string(key) : cat(parent, ".", key);
}

std::string indexPath(std::string_view parent, std::size_t index) {
    return cat(parent, "[", index, "]");
}

std::string describeJsonType(const nlohmann::json& value) {
    switch (value.type()) {
        case nlohmann::json::value_t::null:
            return "null";
        case nlohmann::json::value_t::object:
            return "an object";
        case nlohmann::json::value_t::array:
            return "an array";
        case nlohmann::json::value_t::string:
            return "a string";
        case nlohmann::json::value_t::boolean:
            return "a boolean";
        case nlohmann::json::value_t::number_integer:
        case nlohmann::json::value_t::number_unsigned:
        case nlohmann::json::value_t::number_float:
            return "a number";
        default:
            return "an unsupported value";
    }
}

Json parseJsonDocument(std::string_view text, const JsonLimits& limits) {
    // nlohmann stops at a NUL byte as if the text ended there: a NUL-only file would read as "unexpected
    // end of input", and one after the document would pass unseen. Text files have none.
    if (auto nul = text.find('\0'); nul != std::string_view::npos)
        throw JsonSyntaxError{textPositionOf(text, nul), cat("a NUL byte (code 0): a ", limits.document,
                                                             " file is text, and this one is not")};
    if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
        throw JsonSyntaxError{textPositionOf(text, text.size()),
                              text.empty() ? "the file is empty" : "the file holds only white space"};
    TreeBuilder builder(text, limits);
    Json::sax_parse(text.begin(), text.end(), &builder);
    return builder.take();
}

std::string describeJsonError(std::string_view fileName, const JsonSyntaxError& error) {
    return cat(fileName, ":", error.at.line, ":", error.at.column, ": JSON syntax error: ", error.reason);
}

std::string describeJsonError(std::string_view fileName, const JsonFieldError& error) {
    return cat(fileName, ": ", error.path, ": ", error.reason);
}

Result<Json> readJsonDocument(std::string_view text, std::string_view fileName, const JsonLimits& limits) {
    try {
        return parseJsonDocument(text, limits);
    } catch (const JsonSyntaxError& error) {
        return Error{describeJsonError(fileName, error)};
    } catch (const JsonFieldError& error) {
        return Error{describeJsonError(fileName, error)};
    } catch (const std::exception& error) {
        // Nothing above should get here; if it does, the caller still gets a message instead of a crash.
        return Error{cat(fileName, ": cannot read the ", limits.document, ": ", error.what())};
    }
}

}  // namespace fx
