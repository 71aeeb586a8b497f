#include "base/params.hpp"
#include "base/json_text.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <map>
#include <utility>

#include <nlohmann/json.hpp>

#include "base/json_document.hpp"
#include "base/log.hpp"
#include "base/message_text.hpp"
#include "base/words.hpp"

namespace fx {
namespace {

// Infinity is written as a word: a scene file (JSON) has no number for it.
constexpr std::string_view kInfinity = "infinity";

// A number as messages write it (base/message_text.hpp), as the float every setting and parameter is
// held in (0.02, not 0.019999999552965164), infinity as the word.
std::string numberText(double v) {
    if (std::isinf(v)) return v > 0 ? std::string(kInfinity) : "-" + std::string(kInfinity);
    return formatNumber(static_cast<float>(v));
}

Result<double> parseNumber(std::string_view text) {
    std::string s(text);
    if (s.empty()) return Error{"no value"};
    char* end = nullptr;
    errno = 0;
    double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size()) return Error{cat("\"", excerpt(s), "\" is not a number")};
    if (!std::isfinite(v)) return Error{cat("\"", excerpt(s), "\" is not a finite number")};
    // 1e-400 reads as 0 (ERANGE), and 1e-300 becomes 0 as the float a parameter is held in: refused as
    // a scene refuses them, not taken silently as 0.
    if (errno == ERANGE && std::fabs(v) < 1.0)
        return Error{
            cat("\"", excerpt(s), "\" is too small for a double (it underflows to ", formatNumber(v), ")")};
    if (v != 0.0 && static_cast<float>(v) == 0.0f)
        return Error{cat("\"", excerpt(s), "\" becomes 0 as a float (the precision fxlab computes with)")};
    return v;
}

}  // namespace

std::string_view toString(ParamSource source) {
    switch (source) {
        case ParamSource::lessonDefault:
            return "default";
        case ParamSource::scene:
            return "scene";
        case ParamSource::preset:
            return "preset";
        case ParamSource::commandLine:
            return "command line";
        case ParamSource::overlay:
            return "overlay";
    }
    return "?";
}

ParamSource Param::source() const {
    return get() == originValue ? origin : ParamSource::overlay;
}

double Param::get() const {
    switch (type) {
        case ParamType::Float:
            return *floatValue;
        case ParamType::Int:
        case ParamType::Choice:
            return *intValue;
        case ParamType::Bool:
            return *boolValue ? 1.0 : 0.0;
    }
    return 0;
}

void Param::set(double value) const {
    value = std::clamp(value, min, max);
    switch (type) {
        case ParamType::Float:
            *floatValue = static_cast<float>(value);
            break;
        case ParamType::Int:
        case ParamType::Choice:
            *intValue = static_cast<int>(std::lround(value));
            break;
        case ParamType::Bool:
            *boolValue = value != 0.0;
            break;
    }
}

std::string SettingSpec::rangeText() const {
    if (type == ParamType::Choice) {
        std::string list;
        for (const std::string& c : choices) list += (list.empty() ? "" : ", ") + c;
        return list;
    }
    return cat(minOpen ? "(" : "[", numberText(min), ", ", numberText(max), std::isinf(max) ? ")" : "]");
}

std::string SettingSpec::valueText(double value) const {
    if (type == ParamType::Choice) {
        auto i = static_cast<std::size_t>(std::lround(value));
        return i < choices.size() ? choices[i] : cat(i);
    }
    return numberText(value);
}

std::string Param::valueText(double value) const {
    switch (type) {
        case ParamType::Float:
            return numberText(value);
        case ParamType::Int:
            return cat(static_cast<long>(std::lround(value)));
        case ParamType::Bool:
            return value != 0.0 ? "true" : "false";
        case ParamType::Choice: {
            auto i = static_cast<std::size_t>(std::lround(value));
            return i < choices.size() ? choices[i] : cat(i);
        }
    }
    return {};
}

std::string Param::text() const {
    return valueText(get());
}

std::string Param::rangeText() const {
    switch (type) {
        case ParamType::Float:
            if (std::isinf(max)) return cat("a number from ", numberText(min), " up, or ", kInfinity);
            return cat("a number from ", numberText(min), " to ", numberText(max));
        case ParamType::Int:
            return cat("a whole number from ", static_cast<long>(min), " to ", static_cast<long>(max));
        case ParamType::Bool:
            return "true or false";
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
    p.originValue = p.startValue = p.defaultValue;
    params_.push_back(std::move(p));
    return params_.back();
}

namespace {

Param makeParam(std::string name, std::string description, ParamType type, double min, double max) {
    Param p;
    p.name = std::move(name);
    p.description = std::move(description);
    p.type = type;
    p.min = min;
    p.max = max;
    p.sliderMin = min;  // the slider spans the range unless a setting says otherwise
    p.sliderMax = max;
    return p;
}

}  // namespace

Param& ParamSet::addFloat(std::string name, float* value, float min, float max, std::string description) {
    Param p = makeParam(std::move(name), std::move(description), ParamType::Float, min, max);
    p.floatValue = value;
    return add(std::move(p));
}

Param& ParamSet::addInt(std::string name, int* value, int min, int max, std::string description) {
    Param p = makeParam(std::move(name), std::move(description), ParamType::Int, double(min), double(max));
    p.intValue = value;
    return add(std::move(p));
}

Param& ParamSet::addBool(std::string name, bool* value, std::string description) {
    Param p = makeParam(std::move(name), std::move(description), ParamType::Bool, 0, 1);
    p.boolValue = value;
    return add(std::move(p));
}

namespace {

Param settingParam(std::string name, const SettingSpec& setting, std::string note) {
    Param p = makeParam(std::move(name), note.empty() ? setting.help : cat(note, ": ", setting.help),
                        setting.type, setting.min, setting.max);
    p.choices = setting.choices;
    p.sliderMin = setting.sliderMin;
    p.sliderMax = setting.sliderMax;
    p.sceneSetting = setting.path;
    return p;
}

}  // namespace

Param& ParamSet::addSetting(std::string name, float* value, const SettingSpec& setting, std::string note) {
    Param p = settingParam(std::move(name), setting, std::move(note));
    p.type = ParamType::Float;
    p.floatValue = value;
    *value = static_cast<float>(setting.defaultValue);
    return add(std::move(p));
}

Param& ParamSet::addSetting(std::string name, int* value, const SettingSpec& setting, std::string note) {
    Param p = settingParam(std::move(name), setting, std::move(note));
    if (p.type == ParamType::Float) p.type = ParamType::Int;
    p.intValue = value;
    *value = static_cast<int>(std::lround(setting.defaultValue));
    return add(std::move(p));
}

Param& ParamSet::addChoice(std::string name, int* value, std::vector<std::string> choices,
                           std::string description) {
    double max = choices.empty() ? 0 : double(choices.size() - 1);
    Param p = makeParam(std::move(name), std::move(description), ParamType::Choice, 0, max);
    p.choices = std::move(choices);
    p.intValue = value;
    return add(std::move(p));
}

std::string Param::sliderFormat() const {
    const char* number = type == ParamType::Float ? "%.3f" : "%d";
    if (zeroMeans.empty() || get() != 0.0) return number;
    std::string shown;
    const std::string key = "param." + name + ".zero";
    for (char c : words().language() == "en" ? words().textOr(key, zeroMeans) : say(key))
        shown += c == '%' ? std::string("%%") : std::string(1, c);
    return shown;
}

std::string Param::label() const {
    // English shows the name as typed; another language needs its own label (missing: counted).
    const std::string key = "param." + name + ".label";
    return words().language() == "en" ? words().textOr(key, name) : say(key);
}

std::string Param::help() const {
    // A lesson's parameter has no description: a help its words lack shows (and counts) as missing.
    const std::string key = "param." + name + ".help";
    // English may take a scene setting's help (its description); another language needs its own.
    std::string body =
        description.empty() || words().language() != "en" ? say(key) : words().textOr(key, description);
    if (steps.empty()) return body;
    return say("param.inSteps", {{"steps", stepsText(steps)}, {"help", body}});
}

std::string Param::shownRangeText() const {
    switch (type) {
        case ParamType::Float:
            if (std::isinf(max)) return say("range.numberUp", {{"min", numberText(min)}});
            return say("range.number", {{"min", numberText(min)}, {"max", numberText(max)}});
        case ParamType::Int:
            return say("range.whole",
                       {{"min", cat(static_cast<long>(min))}, {"max", cat(static_cast<long>(max))}});
        case ParamType::Bool:
            return say("range.bool");
        case ParamType::Choice: {
            std::string list;
            for (auto& c : choices) list += (list.empty() ? "" : ", ") + c;
            return say("range.choice", {{"list", list}});
        }
    }
    return {};
}

bool Param::actsIn(int step) const {
    return steps.empty() || std::find(steps.begin(), steps.end(), step) != steps.end();
}

std::vector<const Param*> ParamSet::forStep(int step) const {
    std::vector<const Param*> list;
    for (const Param& p : params_) {
        if (p.actsIn(step)) list.push_back(&p);
    }
    return list;
}

const Param* ParamSet::find(std::string_view name) const {
    for (auto& p : params_) {
        if (p.name == name) return &p;
    }
    return nullptr;
}

Param* ParamSet::findMutable(std::string_view name) {
    return const_cast<Param*>(std::as_const(*this).find(name));
}

void ParamSet::assignFrom(Param& p, double value, ParamSource source) {
    p.set(value);
    p.origin = source;
    p.originValue = p.get();  // after clamping and rounding, as the value is stored
}

void ParamSet::markEdited(const Param& param) {
    if (Param* p = findMutable(param.name)) {
        if (p->origin != ParamSource::overlay) {
            p->stepBaseValue = p->originValue;
            p->stepBaseOrigin = p->origin;
        }
        p->origin = ParamSource::overlay;
        p->originValue = p->get();
    }
}

void ParamSet::changeStep(int from, int to) {
    if (from == to) return;
    for (Param& p : params_) {
        if (p.pinned) continue;
        const bool changed = p.source() == ParamSource::overlay;
        // The value the steps start from: what the value came from before the program changed it.
        const bool overlayOrigin = p.origin == ParamSource::overlay;
        const double baseValue = overlayOrigin ? p.stepBaseValue : p.originValue;
        const ParamSource baseOrigin = overlayOrigin ? p.stepBaseOrigin : p.origin;
        // A value back at the base where it acts is no longer a change there; a change made while a
        // step it does not act in was shown is its steps'.
        std::vector<int> owners{from};
        if (!p.actsIn(from)) owners = changed ? p.steps : std::vector<int>{};
        for (int owner : owners) {
            std::erase_if(p.stepValues, [owner](const auto& v) { return v.first == owner; });
            if (changed) p.stepValues.emplace_back(owner, p.get());
        }
        assignFrom(p, baseValue, baseOrigin);
        p.stepBaseValue = baseValue;
        p.stepBaseOrigin = baseOrigin;
        for (const auto& [step, value] : p.stepValues) {
            if (step != to) continue;
            p.set(value);
            p.origin = ParamSource::overlay;
            p.originValue = p.get();
        }
    }
}

void ParamSet::setPinned(const Param& param, bool pinned) {
    if (Param* p = findMutable(param.name)) p->pinned = pinned;
}

void ParamSet::markStartingValues() {
    for (auto& p : params_) {
        p.startValue = p.get();
        p.startOrigin = p.source();
    }
}

std::vector<const Param*> ParamSet::knobs() const {
    std::vector<const Param*> out;
    for (auto& p : params_) {
        if (p.knob) out.push_back(&p);
    }
    return out;
}

std::vector<ParamSet::Saved> ParamSet::save() const {
    std::vector<Saved> saved;
    for (auto& p : params_) saved.push_back({p.get(), p.origin, p.originValue});
    return saved;
}

void ParamSet::restore(const std::vector<Saved>& saved) {
    for (std::size_t i = 0; i < params_.size() && i < saved.size(); ++i) {
        params_[i].set(saved[i].value);
        params_[i].origin = saved[i].origin;
        params_[i].originValue = saved[i].originValue;
    }
}

void ParamSet::resetAll() {
    for (auto& p : params_) {
        assignFrom(p, p.startValue, p.startOrigin);
        p.stepValues.clear();
        p.pinned = false;
    }
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
            return bad(cat("\"", excerpt(text), "\" is not true or false"));
        case ParamType::Choice: {
            for (std::size_t i = 0; i < p.choices.size(); ++i) {
                if (p.choices[i] == text) return double(i);
            }
            return bad(cat("\"", excerpt(text), "\" is not a choice"));
        }
        case ParamType::Int:
        case ParamType::Float: {
            if (text == kInfinity && std::isinf(p.max)) return p.max;
            auto v = parseNumber(text);
            if (!v) return bad(v.error());
            if (p.type == ParamType::Int && std::floor(*v) != *v)
                return bad(cat(excerpt(text), " is not a whole number"));
            if (*v < p.min || *v > p.max) return bad(cat(excerpt(text), " is out of range"));
            return *v;
        }
    }
    return bad("unknown type");
}

}  // namespace

Status ParamSet::set(std::string_view name, std::string_view text, ParamSource source) {
    Param* p = findMutable(name);
    if (!p) {
        std::string known;
        for (auto& q : params_) known += (known.empty() ? "" : ", ") + q.name;
        return Error{cat("no parameter named \"", excerpt(name),
                         "\"; this lesson has: ", known.empty() ? "(none)" : known)};
    }
    auto v = parseFor(*p, text);
    if (!v) return Error{v.error()};
    assignFrom(*p, *v, source);
    return Status::success();
}

Status ParamSet::assign(std::string_view assignment, ParamSource source) {
    auto eq = assignment.find('=');
    if (eq == std::string_view::npos || eq == 0) {
        return Error{cat("\"", excerpt(assignment), "\" is not of the form name=value")};
    }
    return set(assignment.substr(0, eq), assignment.substr(eq + 1), source);
}

Status ParamSet::applyScene(const std::vector<SettingText>& settings, const std::vector<std::string>& known,
                            std::string_view sceneFile) {
    std::vector<std::pair<Param*, double>> checked;
    for (auto& p : params_) {
        if (p.sceneSetting.empty()) continue;
        if (std::find(known.begin(), known.end(), p.sceneSetting) == known.end()) {
            return Error{cat("parameter ", p.name, " starts from the scene setting \"", p.sceneSetting,
                             "\", which scene files do not have")};
        }
        for (const SettingText& s : settings) {
            if (s.setting != p.sceneSetting) continue;
            auto v = parseFor(p, s.text);
            if (!v) return Error{cat(sceneFile, ": ", s.setting, ": ", v.error())};
            checked.emplace_back(&p, *v);
        }
    }
    for (auto& [p, v] : checked) assignFrom(*p, v, ParamSource::scene);
    return Status::success();
}

std::vector<std::string> ParamSet::unusedSettings(const std::vector<SettingText>& settings,
                                                  const std::vector<SettingText>& defaults) const {
    // "postEffects.bloom.knee" is in the group "postEffects.bloom".
    auto group = [](const std::string& setting) { return setting.substr(0, setting.rfind('.')); };
    std::vector<std::string> unused;
    for (const SettingText& s : settings) {
        const bool used = std::any_of(params_.begin(), params_.end(),
                                      [&](const Param& p) { return p.sceneSetting == s.setting; });
        const bool atDefault = std::any_of(defaults.begin(), defaults.end(), [&](const SettingText& d) {
            return d.setting == s.setting && d.text == s.text;
        });
        const bool groupRead = std::any_of(params_.begin(), params_.end(), [&](const Param& p) {
            return !p.sceneSetting.empty() && group(p.sceneSetting) == group(s.setting);
        });
        if (!used && !atDefault && groupRead) unused.push_back(s.setting);
    }
    return unused;
}

std::string ParamSet::toJson() const {
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    for (auto& p : params_) j[p.name] = p.text();
    return dumpJson(j, 2) + "\n";
}

Status ParamSet::fromJson(std::string_view json, std::string_view fileName, ParamSource source) {
    // The scenes' strict reader: a key given twice, a NUL byte or an over-long string is refused, and a
    // syntax error says where. A preset is one flat object of short values.
    auto document = readJsonDocument(json, fileName, {"preset", 4096, 8});
    if (!document) return Error{document.error()};
    const nlohmann::json& j = *document;
    if (!j.is_object())
        return Error{
            cat(fileName, ": expected an object of parameter names to values, got ", describeJsonType(j))};
    std::vector<std::pair<Param*, double>> checked;
    for (auto& [key, value] : j.items()) {
        Param* p = findMutable(key);
        if (!p) return Error{cat(fileName, ": ", excerpt(key), ": no such parameter")};
        if (!value.is_string() && !value.is_number() && !value.is_boolean())
            return Error{
                cat(fileName, ": ", key, ": expected a number or a string, got ", describeJsonType(value))};
        std::string text = value.is_string() ? value.get<std::string>() : dumpJson(value);
        auto v = parseFor(*p, text);
        if (!v) return Error{cat(fileName, ": ", key, ": ", v.error())};
        checked.emplace_back(p, *v);
    }
    for (auto& [p, v] : checked) assignFrom(*p, v, source);
    return Status::success();
}

}  // namespace fx
