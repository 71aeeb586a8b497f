#pragma once
// Reads one JSON object of a scene file field by field and checks each value as it goes: type, vector
// length, finiteness, range, enumeration names. Every complaint names the field by its JSON path
// ("objects[2].material.emissive[1]"). Fields nobody asked for are reported as unknown, with the nearest
// known name as a suggestion.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>

#include "base/json_document.hpp"
#include "base/log.hpp"
#include "base/message_text.hpp"
#include "scene/closest_name.hpp"
#include "scene/scene_enums.hpp"
#include "scene/scene_limits.hpp"

namespace fx {

// What the scene reader throws at the first bad value (failField, base/json_document.hpp). parseScene
// catches it and returns an Error that names the file; no exception leaves the loader. Throwing keeps the
// many reads free of error plumbing.
using SceneFieldError = JsonFieldError;

// An interval of allowed numbers. Every range is bounded, so a value that passes fits in a float.
struct NumberRange {
    double low = -1.0e6;
    double high = 1.0e6;
    bool lowOpen = false;
    bool highOpen = false;

    static NumberRange closed(double low, double high) { return {low, high, false, false}; }
    static NumberRange aboveZero(double high) { return {0.0, high, true, false}; }  // (0, high]
    static NumberRange open(double low, double high) { return {low, high, true, true}; }

    bool contains(double value) const;
    std::string text() const;  // "(0, 180)", "[1, 512]"
};

// Value readers for one JSON value at `path`.
// The number as the float the program will use; the range is checked on that float too.
float readNumber(const nlohmann::json& value, const std::string& path, NumberRange range);
int readInteger(const nlohmann::json& value, const std::string& path, NumberRange range);
void readNumbers(const nlohmann::json& value, const std::string& path, float* out, int count,
                 NumberRange range);

class JsonFieldReader {
public:
    // Refuses (throws SceneFieldError) when `value` is not an object. Unknown fields go to `warnings`.
    JsonFieldReader(const nlohmann::json& value, std::string path, std::vector<std::string>& warnings);

    const std::string& path() const { return path_; }
    std::string pathOf(std::string_view key) const { return fieldPath(path_, key); }

    // Each accessor marks `key` as known. The required ones refuse a missing field; the others return
    // `fallback` when the field is absent.
    bool has(std::string_view key);
    const nlohmann::json& required(std::string_view key);

    float number(std::string_view key, float fallback, NumberRange range);
    float requiredNumber(std::string_view key, NumberRange range);
    int integer(std::string_view key, int fallback, NumberRange range);
    bool boolean(std::string_view key, bool fallback);
    std::string text(std::string_view key, std::string fallback);
    std::string requiredText(std::string_view key);
    glm::vec2 vec2(std::string_view key, glm::vec2 fallback, NumberRange range);
    glm::vec3 vec3(std::string_view key, glm::vec3 fallback, NumberRange range);
    glm::vec3 requiredVec3(std::string_view key, NumberRange range);
    glm::vec4 vec4(std::string_view key, glm::vec4 fallback, NumberRange range);

    template <class E>
    E enumeration(std::string_view key, E fallback) {
        return has(key) ? enumValue<E>(key) : fallback;
    }
    template <class E>
    E requiredEnumeration(std::string_view key) {
        required(key);
        return enumValue<E>(key);
    }

    JsonFieldReader object(std::string_view key);  // required
    // A reader for a nested value this reader found by other means (an element of a fixed-size array).
    JsonFieldReader child(const nlohmann::json& value, std::string path) {
        return JsonFieldReader(value, std::move(path), warnings_);
    }
    // Calls visit(JsonFieldReader&) for each element of an optional array of at most `maxCount` objects.
    template <class Visit>
    void forEachObject(std::string_view key, std::size_t maxCount, Visit visit) {
        if (!has(key)) return;
        const nlohmann::json& array = *find(key);
        if (!array.is_array())
            failField(pathOf(key), cat("expected an array, got ", describeJsonType(array)));
        if (array.size() > maxCount)
            failField(pathOf(key), cat(array.size(), " entries; a scene may have at most ", maxCount,
                                       " (docs/scene-format.md, Limits)"));
        for (std::size_t i = 0; i < array.size(); ++i) {
            JsonFieldReader element(array[i], indexPath(pathOf(key), i), warnings_);
            visit(element);
        }
    }

    // A field this object knows but does not use in its current form (a cone angle on a point light):
    // warns with `why` when present.
    void unused(std::string_view key, std::string_view why);
    void warn(std::string_view key, std::string_view message);
    [[noreturn]] void fail(std::string_view key, std::string reason) {
        failField(pathOf(key), std::move(reason));
    }

    // Warns about every field no accessor asked for. `kind` says what the keys are ("field", "post effect").
    void reportUnknown(std::string_view kind = "field");

private:
    const nlohmann::json* find(std::string_view key);

    template <class E>
    E enumValue(std::string_view key) {
        const nlohmann::json& value = *find(key);
        if (!value.is_string())
            failField(pathOf(key), cat("expected a string, got ", describeJsonType(value)));
        const auto& name = value.get_ref<const std::string&>();
        if (auto parsed = enumFromName<E>(name)) return *parsed;
        std::vector<std::string> names;
        for (const auto& entry : enumNames(E{})) names.emplace_back(entry.name);
        std::string hint;
        if (auto near = closestName(name, names)) hint = cat(" (did you mean \"", *near, "\"?)");
        failField(pathOf(key),
                  cat("unknown value \"", excerpt(name), "\"", hint, "; allowed: ", allowedNames<E>()));
    }

    const nlohmann::json& value_;
    std::string path_;
    std::vector<std::string>& warnings_;
    std::vector<std::string> known_;
};

}  // namespace fx
