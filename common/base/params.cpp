#include "base/params.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>

#include <nlohmann/json.hpp>

#include "base/log.hpp"

namespace fx {
namespace {

std::string formatNumber(double v) {
    std::string s = cat(v);
    return s;
}

Result<double> parseNumber(std::string_view text) {
    std::string s(text);
    if (s.empty()) return Error{"no value"};
    char* end = nullptr;
    double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size()) return Error{cat("\"", s, "\" is not a number")};
    if (!std::isfinite(v)) return Error{cat("\"", s, "\" is not a finite number")};
    return v;
}

}  // namespace

double Param::get() const {
    switch (type) {
        case ParamType::Float: return *floatValue;
        case ParamType::Int:
        case ParamType::Choice: return *intValue;
        case ParamType::Bool: return *boolValue ? 1.0 : 0.0;
    }
    return 0;
}

void Param::set(double value) const {
    value = std::clamp(value, min, max);
    switch (type) {
        case ParamType::Float: *floatValue = static_cast<float>(value); break;
        case ParamType::Int:
        case ParamType::Choice: *intValue = static_cast<int>(std::lround(value)); break;
        case ParamType::Bool: *boolValue = value != 0.0; break;
    }
}

std::string Param::valueText(double value) const {
    switch (type) {
        case ParamType::Float: return formatNumber(value);
        case ParamType::Int: return cat(static_cast<long>(std::lround(value)));
        case ParamType::Bool: return value != 0.0 ? "true" : "false";
        case ParamType::Choice: {
            auto i = static_cast<std::size_t>(std::lround(value));
            return i < choices.size() ? choices[i] : cat(i);
        }
    }
    return {};
}

std::string Param::text() const { return valueText(get()); }

std::string Param::rangeText() const {
    switch (type) {
        case ParamType::Float: return cat("a number from ", formatNumber(min), " to ", formatNumber(max));
        case ParamType::Int: return cat("a whole number from ", static_cast<long>(min), " to ", static_cast<long>(max));
        case ParamType::Bool: return "true or false";
        case ParamType::Choice: {
            std::string list;
            for (auto& c : choices) list += (list.empty() ? "" : ", ") + c;
            return "one of: " + list;
        }
    }
    return {};
}

Param& ParamSet::add(Param p) {
    p.defaultValue = p.get();
    params_.push_back(std::move(p));
    return params_.back();
}

Param& ParamSet::addFloat(std::string name, float* value, float min, float max, std::string description) {
    Param p{std::move(name), std::move(description), ParamType::Float, min, max, {}, 0, {}, value, nullptr, nullptr};
    return add(std::move(p));
}

Param& ParamSet::addInt(std::string name, int* value, int min, int max, std::string description) {
    Param p{std::move(name), std::move(description), ParamType::Int, double(min), double(max), {}, 0, {}, nullptr, value, nullptr};
    return add(std::move(p));
}

Param& ParamSet::addBool(std::string name, bool* value, std::string description) {
    Param p{std::move(name), std::move(description), ParamType::Bool, 0, 1, {}, 0, {}, nullptr, nullptr, value};
    return add(std::move(p));
}

Param& ParamSet::addChoice(std::string name, int* value, std::vector<std::string> choices, std::string description) {
    double max = choices.empty() ? 0 : double(choices.size() - 1);
    Param p{std::move(name), std::move(description), ParamType::Choice, 0, max, std::move(choices), 0, {}, nullptr, value, nullptr};
    return add(std::move(p));
}

const Param* ParamSet::find(std::string_view name) const {
    for (auto& p : params_) {
        if (p.name == name) return &p;
    }
    return nullptr;
}

std::vector<const Param*> ParamSet::knobs() const {
    std::vector<const Param*> out;
    for (auto& p : params_) {
        if (p.knob) out.push_back(&p);
    }
    return out;
}

void ParamSet::resetAll() const {
    for (auto& p : params_) p.set(p.defaultValue);
}

namespace {

Result<double> parseFor(const Param& p, std::string_view text) {
    auto bad = [&](const std::string& why) {
        return Error{cat("parameter ", p.name, ": ", why, "; expected ", p.rangeText())};
    };
    switch (p.type) {
        case ParamType::Bool:
            if (text == "true" || text == "1" || text == "on") return 1.0;
            if (text == "false" || text == "0" || text == "off") return 0.0;
            return bad(cat("\"", text, "\" is not true or false"));
        case ParamType::Choice: {
            for (std::size_t i = 0; i < p.choices.size(); ++i) {
                if (p.choices[i] == text) return double(i);
            }
            return bad(cat("\"", text, "\" is not a choice"));
        }
        case ParamType::Int:
        case ParamType::Float: {
            auto v = parseNumber(text);
            if (!v) return bad(v.error());
            if (p.type == ParamType::Int && std::floor(*v) != *v) return bad(cat(text, " is not a whole number"));
            if (*v < p.min || *v > p.max) return bad(cat(text, " is out of range"));
            return *v;
        }
    }
    return bad("unknown type");
}

}  // namespace

Status ParamSet::set(std::string_view name, std::string_view text) {
    const Param* p = find(name);
    if (!p) {
        std::string known;
        for (auto& q : params_) known += (known.empty() ? "" : ", ") + q.name;
        return Error{cat("no parameter named \"", name, "\"; this lesson has: ", known.empty() ? "(none)" : known)};
    }
    auto v = parseFor(*p, text);
    if (!v) return Error{v.error()};
    p->set(*v);
    return Status::success();
}

Status ParamSet::assign(std::string_view assignment) {
    auto eq = assignment.find('=');
    if (eq == std::string_view::npos || eq == 0) {
        return Error{cat("\"", assignment, "\" is not of the form name=value")};
    }
    return set(assignment.substr(0, eq), assignment.substr(eq + 1));
}

std::string ParamSet::toJson() const {
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    for (auto& p : params_) j[p.name] = p.text();
    return j.dump(2) + "\n";
}

Status ParamSet::fromJson(std::string_view json, std::string_view fileName) {
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(json);
    } catch (const nlohmann::json::parse_error& e) {
        return Error{cat(fileName, ": not valid JSON (", e.what(), ")")};
    }
    if (!j.is_object()) return Error{cat(fileName, ": expected an object of parameter names to values")};
    std::vector<std::pair<const Param*, double>> checked;
    for (auto& [key, value] : j.items()) {
        const Param* p = find(key);
        if (!p) return Error{cat(fileName, ": ", key, ": no such parameter")};
        std::string text = value.is_string() ? value.get<std::string>() : value.dump();
        auto v = parseFor(*p, text);
        if (!v) return Error{cat(fileName, ": ", key, ": ", v.error())};
        checked.emplace_back(p, *v);
    }
    for (auto& [p, v] : checked) p->set(v);
    return Status::success();
}

}  // namespace fx
