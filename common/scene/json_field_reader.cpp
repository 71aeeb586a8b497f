#include "scene/json_field_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "base/log.hpp"
#include "base/message_text.hpp"
#include "scene/scene_limits.hpp"

namespace fx {

bool NumberRange::contains(double value) const {
    bool aboveLow = lowOpen ? value > low : value >= low;
    bool belowHigh = highOpen ? value < high : value <= high;
    return aboveLow && belowHigh;
}

std::string NumberRange::text() const {
    return cat(lowOpen ? "(" : "[", formatNumber(low), ", ", formatNumber(high), highOpen ? ")" : "]");
}

float readNumber(const nlohmann::json& value, const std::string& path, NumberRange range) {
    if (!value.is_number()) failField(path, cat("expected a number, got ", describeJsonType(value)));
    double number = value.get<double>();
    // JSON has no NaN or infinity, but a literal such as 1e400 parses as infinity.
    if (!std::isfinite(number))
        failField(path, "the number is not finite (too large for a double: it overflowed)");
    if (!range.contains(number))
        failField(path, cat(formatNumber(number), " is out of range ", range.text()));
    // The program uses the value as a float: 1e-300 passes as a double and is 0 as a float, and
    // 179.99999999 rounds up to 180. Check what the program will see.
    const float asFloat = static_cast<float>(number);
    if (!range.contains(double(asFloat)))
        failField(path, cat(formatNumber(number), " becomes ", formatNumber(asFloat),
                            " as a float (the precision fxlab computes with), which is out of range ",
                            range.text()));
    return asFloat;
}

int readInteger(const nlohmann::json& value, const std::string& path, NumberRange range) {
    if (!value.is_number()) failField(path, cat("expected an integer, got ", describeJsonType(value)));
    double number = value.get<double>();
    if (value.is_number_unsigned()) number = static_cast<double>(value.get<std::uint64_t>());
    if (value.is_number_float() && (!std::isfinite(number) || std::floor(number) != number))
        failField(path, cat("expected an integer, got ", formatNumber(number)));
    if (!range.contains(number))
        failField(path, cat(formatNumber(number), " is out of range ", range.text()));
    return static_cast<int>(number);
}

void readNumbers(const nlohmann::json& value, const std::string& path, float* out, int count,
                 NumberRange range) {
    if (!value.is_array())
        failField(path, cat("expected an array of ", count, " numbers, got ", describeJsonType(value)));
    if (value.size() != static_cast<std::size_t>(count))
        failField(path, cat("expected ", count, " numbers, got ", value.size()));
    for (int i = 0; i < count; ++i)
        out[i] = readNumber(value[static_cast<std::size_t>(i)], indexPath(path, static_cast<std::size_t>(i)),
                            range);
}

JsonFieldReader::JsonFieldReader(const nlohmann::json& value, std::string path,
                                 std::vector<std::string>& warnings)
    : value_(value), path_(std::move(path)), warnings_(warnings) {
    if (!value_.is_object())
        failField(path_.empty() ? "(top level)" : path_,
                  cat("expected an object, got ", describeJsonType(value_)));
}

const nlohmann::json* JsonFieldReader::find(std::string_view key) {
    if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.emplace_back(key);
    auto it = value_.find(key);
    return it == value_.end() ? nullptr : &*it;
}

bool JsonFieldReader::has(std::string_view key) {
    return find(key) != nullptr;
}

const nlohmann::json& JsonFieldReader::required(std::string_view key) {
    const nlohmann::json* value = find(key);
    if (!value) failField(pathOf(key), "missing required field");
    return *value;
}

float JsonFieldReader::number(std::string_view key, float fallback, NumberRange range) {
    const nlohmann::json* value = find(key);
    return value ? readNumber(*value, pathOf(key), range) : fallback;
}

float JsonFieldReader::requiredNumber(std::string_view key, NumberRange range) {
    return readNumber(required(key), pathOf(key), range);
}

int JsonFieldReader::integer(std::string_view key, int fallback, NumberRange range) {
    const nlohmann::json* value = find(key);
    return value ? readInteger(*value, pathOf(key), range) : fallback;
}

bool JsonFieldReader::boolean(std::string_view key, bool fallback) {
    const nlohmann::json* value = find(key);
    if (!value) return fallback;
    if (!value->is_boolean()) fail(key, cat("expected true or false, got ", describeJsonType(*value)));
    return value->get<bool>();
}

std::string JsonFieldReader::text(std::string_view key, std::string fallback) {
    const nlohmann::json* value = find(key);
    if (!value) return fallback;
    if (!value->is_string()) fail(key, cat("expected a string, got ", describeJsonType(*value)));
    return value->get<std::string>();
}

std::string JsonFieldReader::requiredText(std::string_view key) {
    required(key);
    return text(key, {});
}

glm::vec2 JsonFieldReader::vec2(std::string_view key, glm::vec2 fallback, NumberRange range) {
    const nlohmann::json* value = find(key);
    if (!value) return fallback;
    float v[2];
    readNumbers(*value, pathOf(key), v, 2, range);
    return {v[0], v[1]};
}

glm::vec3 JsonFieldReader::vec3(std::string_view key, glm::vec3 fallback, NumberRange range) {
    const nlohmann::json* value = find(key);
    if (!value) return fallback;
    float v[3];
    readNumbers(*value, pathOf(key), v, 3, range);
    return {v[0], v[1], v[2]};
}

glm::vec3 JsonFieldReader::requiredVec3(std::string_view key, NumberRange range) {
    required(key);
    return vec3(key, glm::vec3(0.0f), range);
}

glm::vec4 JsonFieldReader::vec4(std::string_view key, glm::vec4 fallback, NumberRange range) {
    const nlohmann::json* value = find(key);
    if (!value) return fallback;
    float v[4];
    readNumbers(*value, pathOf(key), v, 4, range);
    return {v[0], v[1], v[2], v[3]};
}

JsonFieldReader JsonFieldReader::object(std::string_view key) {
    return JsonFieldReader(required(key), pathOf(key), warnings_);
}

void JsonFieldReader::warn(std::string_view key, std::string_view message) {
    warnings_.push_back(cat(pathOf(key), ": ", message));
}

void JsonFieldReader::unused(std::string_view key, std::string_view why) {
    if (has(key)) warn(key, cat("ignored: ", why));
}

void JsonFieldReader::reportUnknown(std::string_view kind) {
    for (auto it = value_.begin(); it != value_.end(); ++it) {
        if (std::find(known_.begin(), known_.end(), it.key()) != known_.end()) continue;
        std::string hint;
        if (auto near = closestName(it.key(), known_)) hint = cat(" (did you mean \"", *near, "\"?)");
        warnings_.push_back(cat(pathOf(excerpt(it.key())), ": unknown ", kind, ", ignored", hint));
    }
}

}  // namespace fx
