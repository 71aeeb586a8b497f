#pragma once
// A lesson's parameters: named values bound to the lesson's own fields, with types and ranges that
// the command line (--param name=value), the overlay and preset files all check the same way.
// A quality knob is a parameter with a list of settings to sweep and one reference setting.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.hpp"

namespace fx {

enum class ParamType { Float, Int, Bool, Choice };

struct Knob {
    std::vector<double> values;  // the settings the bench and the cost panel sweep
    double reference = 0;        // the setting whose image counts as right
    std::string unit;            // "samples", "texels"...
};

struct Param {
    std::string name;         // command-line name: lower case with underscores
    std::string description;  // one sentence for the overlay and --list-params
    ParamType type = ParamType::Float;
    double min = 0, max = 1;
    std::vector<std::string> choices;  // for Choice: the names, stored as an index
    double defaultValue = 0;
    std::optional<Knob> knob;
    // Where the value lives: exactly one is set, matching `type`.
    float* floatValue = nullptr;
    int* intValue = nullptr;
    bool* boolValue = nullptr;

    double get() const;
    void set(double value) const;  // clamps into range
    std::string text() const;      // the current value as --param would take it
    std::string rangeText() const; // "0 to 1", "one of: none, grayscale, sepia"
    std::string valueText(double value) const;
};

class ParamSet {
public:
    Param& addFloat(std::string name, float* value, float min, float max, std::string description);
    Param& addInt(std::string name, int* value, int min, int max, std::string description);
    Param& addBool(std::string name, bool* value, std::string description);
    Param& addChoice(std::string name, int* value, std::vector<std::string> choices, std::string description);

    // Checks the text against the type and range; on error names the parameter and what is allowed,
    // and leaves the value as it was.
    Status set(std::string_view name, std::string_view text);
    // "name=value", as --param takes it.
    Status assign(std::string_view assignment);

    const Param* find(std::string_view name) const;
    const std::vector<Param>& all() const { return params_; }
    std::vector<const Param*> knobs() const;
    void resetAll() const;

    // Preset files: a JSON object of name -> value text. Loading checks every entry first and
    // changes nothing if one is bad.
    std::string toJson() const;
    Status fromJson(std::string_view json, std::string_view fileName);

private:
    std::vector<Param> params_;
    Param& add(Param p);
};

}  // namespace fx
