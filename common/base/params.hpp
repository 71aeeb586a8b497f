#pragma once
// A lesson's parameters: named values bound to the lesson's own fields, with types and ranges that
// the command line (--param name=value), the overlay and preset files all check the same way.
// A quality knob is a parameter with a list of settings to sweep and one reference setting.
//
// Every value remembers where it came from: the lesson's default, the scene file (a parameter may name
// the scene setting that gives its starting value), a preset file, the command line, or the overlay.
// The runner applies them in that order, so each later source overrides the earlier ones.
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "base/result.hpp"

namespace fx {

enum class ParamType { Float, Int, Bool, Choice };

enum class ParamSource { lessonDefault, scene, preset, commandLine, overlay };
// "default", "scene", "preset", "command line", "overlay".
std::string_view toString(ParamSource source);

// A setting read from a file, by its path in that file, as text the parameter parser takes:
// {"postEffects.bloom.threshold", "1.5"}.
struct SettingText {
    std::string setting;
    std::string text;
};

// One setting of a scene file that a parameter can start from, declared once (scene/scene_settings.cpp
// has them all): where it is in the file, the values it may take, what a file that leaves it out gets,
// and what it is. The scene reader checks the file against it, docs/scene-format.md shows it, and a
// parameter that starts from it takes its range, default and help from it (ParamSet::addSetting).
struct SettingSpec {
    std::string path;                     // "postEffects.bloom.threshold"
    ParamType type = ParamType::Float;    // Float, Int or Choice
    double min = 0, max = 1;              // the values that mean something; max may be infinity
    bool minOpen = false;                 // min itself is not one: (min, max]
    std::vector<std::string> choices;     // Choice: the names, as the file writes them
    double defaultValue = 0;              // a Choice's: the index of its name
    bool required = false;                // the file must give it when it has the object it is in
    double sliderMin = 0, sliderMax = 1;  // the overlay's slider: the span a lesson is shown with
    std::string unit;                     // "m", "mm", "px", or empty
    std::string help;                     // one sentence: the overlay, --list-params and the docs

    std::string rangeText() const;              // "[0, 10000]", "(0, infinity)", "clip, reinhard, filmic"
    std::string valueText(double value) const;  // "1", "0.5", "infinity", "filmic"
};

struct Knob {
    std::vector<double> values;  // the settings the bench and the cost panel sweep
    double reference = 0;        // the setting whose image counts as right
    std::string unit;            // "samples", "texels"...
};

struct Param {
    std::string name;  // command-line name: lower case with underscores
    // What the parameter does, in English, where no words file gives it (a setting's help, a test's
    // parameter); a lesson's parameters take their help from its words files (help()).
    std::string description;
    ParamType type = ParamType::Float;
    double min = 0, max = 1;  // max may be infinity (a focus distance): --param takes "infinity"
    // The overlay's slider shows this span (the whole range unless a setting says otherwise: a
    // threshold may be 10000, but the slider that finds one is 0 to 16).
    double sliderMin = 0, sliderMax = 1;
    std::vector<std::string> choices;  // for Choice: the names, stored as an index
    double defaultValue = 0;
    std::optional<Knob> knob;
    // Where the value lives: exactly one is set, matching `type`.
    float* floatValue = nullptr;
    int* intValue = nullptr;
    bool* boolValue = nullptr;
    // The scene setting that gives the starting value ("postEffects.bloom.threshold"); empty: none.
    std::string sceneSetting;
    // Where the value came from and the value it gave then. A value that differs from that now was
    // changed by the running program (the overlay's widgets, a drag in the picture).
    ParamSource origin = ParamSource::lessonDefault;
    double originValue = 0;
    // What "Reset" goes back to: the value and source the run started with.
    double startValue = 0;
    ParamSource startOrigin = ParamSource::lessonDefault;

    // What 0 stands for when it is not an amount but a choice ("the step's own", "off"): the overlay's
    // slider shows these words at 0 instead of the number. Empty: 0 is a number like any other.
    std::string zeroMeans;

    // The steps (0-based) the parameter acts in; empty: every step. The overlay lists only the
    // parameters of the step on screen, so a step never shows another step's settings.
    std::vector<int> steps;

    // A value changed in the running program belongs to the step it was changed in (ParamSet::changeStep):
    // the value changed in each step (0-based), the value every other step starts from (what the run, a
    // preset or Reset gave before the change), and whether the teacher pinned it for every step.
    std::vector<std::pair<int, double>> stepValues;
    double stepBaseValue = 0;
    ParamSource stepBaseOrigin = ParamSource::lessonDefault;
    bool pinned = false;

    // Names the scene setting that gives this parameter its starting value.
    Param& fromScene(std::string setting) {
        sceneSetting = std::move(setting);
        return *this;
    }
    // The parameter acts only in these steps (0-based).
    Param& inSteps(std::vector<int> only) {
        steps = std::move(only);
        return *this;
    }
    // At 0 the slider says the words of "param.<name>.zero" ("the step's own") instead of 0; `words`
    // where no words file has them.
    Param& showZeroAs(std::string words = "0") {
        zeroMeans = std::move(words);
        return *this;
    }
    // The words the overlay shows for it, in the run's language (base/words.hpp): its label
    // ("param.<name>.label"; the name where the words have none, as in English), and its help:
    // "param.<name>.help" (else `description`), after the steps it acts in, named from `steps`
    // ("Steps 3 to 6: ..."), so the help and the code cannot disagree.
    std::string label() const;
    std::string help() const;
    // The range in the run's words ("a number from 0 to 4"; rangeText() is the command line's).
    std::string shownRangeText() const;
    bool actsIn(int step) const;
    ParamSource source() const;
    // The printf format the overlay's slider draws the value with: the number's, or at 0 the words of
    // zeroMeans (with any % doubled, so the slider prints them as they are).
    std::string sliderFormat() const;

    double get() const;
    void set(double value) const;   // clamps into range
    std::string text() const;       // the current value as --param would take it
    std::string rangeText() const;  // "0 to 1", "one of: none, grayscale, sepia"
    std::string valueText(double value) const;
};

// A choice parameter's value as the enumeration the lesson means, its enumerators numbered from 0 in
// the order of the choice's names. The set stores the index and keeps it in range, so reading it
// (`*toneCurve_`) needs no clamp and no cast.
template <class E>
class Choice {
public:
    constexpr Choice() = default;  // the first enumerator, until a setting's default replaces it
    constexpr explicit Choice(E value) : index_(static_cast<int>(value)) {}
    constexpr E operator*() const { return static_cast<E>(index_); }
    int* index() { return &index_; }

private:
    int index_ = 0;
};

// A choice parameter whose names each stand for a value the lesson uses (a format, a matrix, an order
// of effects): one table lists every name beside its value, the parameter offers the names, and
// `*choice` is the chosen value. The set keeps the index in range, so reading it needs no clamp.
template <class T>
class TableChoice {
public:
    struct Option {
        std::string name;
        T value;
    };
    // Starts at the option named `initial`; a name the table lacks is the lesson's mistake.
    TableChoice(std::vector<Option> options, std::string_view initial) : options_(std::move(options)) {
        while (index_ < int(options_.size()) && options_[std::size_t(index_)].name != initial) ++index_;
        if (index_ == int(options_.size()))
            throw std::invalid_argument("TableChoice: no option named " + std::string(initial));
    }
    const T& operator*() const { return options_[std::size_t(index_)].value; }
    const T* operator->() const { return &**this; }
    const std::string& name() const { return options_[std::size_t(index_)].name; }
    std::vector<std::string> names() const {
        std::vector<std::string> out;
        for (const Option& o : options_) out.push_back(o.name);
        return out;
    }
    int* index() { return &index_; }

private:
    std::vector<Option> options_;
    int index_ = 0;
};

class ParamSet {
public:
    // A lesson gives no description: its words files give the help (Param::help()).
    Param& addFloat(std::string name, float* value, float min, float max, std::string description = {});
    Param& addInt(std::string name, int* value, int min, int max, std::string description = {});
    Param& addBool(std::string name, bool* value, std::string description = {});
    Param& addChoice(std::string name, int* value, std::vector<std::string> choices,
                     std::string description = {});
    // A parameter that starts from a scene setting: its range, slider, help and default are the
    // setting's (`*value` is set to the default), and it starts from the scene's value. `note` goes
    // before the help in --list-params (a lesson's steps come from Param::steps instead). The value's type
    // follows the member: a float or an int (a Choice setting needs an int).
    Param& addSetting(std::string name, float* value, const SettingSpec& setting, std::string note = {});
    Param& addSetting(std::string name, int* value, const SettingSpec& setting, std::string note = {});
    template <class E>
    Param& addChoice(std::string name, Choice<E>* value, std::vector<std::string> choices,
                     std::string description = {}) {
        return addChoice(std::move(name), value->index(), std::move(choices), std::move(description));
    }
    // The names are the table's.
    template <class T>
    Param& addChoice(std::string name, TableChoice<T>* value, std::string description = {}) {
        return addChoice(std::move(name), value->index(), value->names(), std::move(description));
    }
    template <class E>
    Param& addSetting(std::string name, Choice<E>* value, const SettingSpec& setting, std::string note = {}) {
        return addSetting(std::move(name), value->index(), setting, std::move(note));
    }

    // Checks the text against the type and range; on error names the parameter and what is allowed,
    // and leaves the value as it was.
    Status set(std::string_view name, std::string_view text, ParamSource source = ParamSource::commandLine);
    // "name=value", as --param takes it.
    Status assign(std::string_view assignment, ParamSource source = ParamSource::commandLine);

    // A scene's settings: every parameter bound to a setting in `settings` takes its value (source
    // scene). `known` lists every setting a scene can have; a parameter bound to another one is a
    // mistake in the lesson. All are checked first; on error nothing changes, and the error names the
    // file, the setting and the parameter's range.
    Status applyScene(const std::vector<SettingText>& settings, const std::vector<std::string>& known,
                      std::string_view sceneFile);
    // The settings in `settings` that no parameter takes but that a user could have meant for this
    // lesson: set to something other than its default (`defaults`; a field a file leaves out reads as
    // its default, so a setting at its default may not have been written at all), in a group
    // ("postEffects.bloom") of which the lesson does read another setting. A lesson without bloom is
    // not told about the bloom of another lesson's scene.
    std::vector<std::string> unusedSettings(const std::vector<SettingText>& settings,
                                            const std::vector<SettingText>& defaults) const;

    // The overlay changed this parameter.
    void markEdited(const Param& param);
    // The step shown changes from `from` to `to` (0-based): each value changed in the running program
    // (source overlay) is kept as the step's own where it was changed (a change made while the step
    // shown is not one the parameter acts in belongs to the steps it acts in), and every parameter that
    // is not pinned takes `to`'s value: the one changed there, or else the one the steps start from. So
    // a step opens with its own values, never with a change made for another step's point.
    void changeStep(int from, int to);
    // Pinned: the value stays whatever the step (until unpinned or Reset).
    void setPinned(const Param& param, bool pinned);
    // The current values become what resetAll() returns to (the runner calls this once the scene,
    // preset and command line are applied).
    void markStartingValues();

    const Param* find(std::string_view name) const;
    // The parameters that act in `step` (0-based), in the order they were added.
    std::vector<const Param*> forStep(int step) const;
    const std::vector<Param>& all() const { return params_; }
    std::vector<const Param*> knobs() const;
    // Back to the starting values (the lesson's defaults until markStartingValues()), in every step:
    // the steps' changes are forgotten and nothing stays pinned.
    void resetAll();

    // Every value with its source, to put back after a temporary change (the bench's sweep).
    struct Saved {
        double value;
        ParamSource origin;
        double originValue;
    };
    std::vector<Saved> save() const;
    void restore(const std::vector<Saved>& saved);

    // Preset files: a JSON object of name -> value text. Loading checks every entry first and
    // changes nothing if one is bad.
    std::string toJson() const;
    Status fromJson(std::string_view json, std::string_view fileName,
                    ParamSource source = ParamSource::preset);

private:
    std::vector<Param> params_;
    Param& add(Param p);
    Param* findMutable(std::string_view name);
    static void assignFrom(Param& p, double value, ParamSource source);
};

}  // namespace fx
