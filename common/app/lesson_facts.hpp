#pragma once
// What a lesson computes or measures about its frame, in one list: the overlay shows it under the
// lesson's panel and the run report writes it under "facts". A lesson fills it once
// (Lesson::facts); no fact is computed twice.
#include <string>
#include <vector>

#include "base/words.hpp"

namespace fx {

struct Fact {
    std::string name;   // the report's key ("uniformLookupsLastFrame"); smoke scripts read some
    std::string value;  // "true" and "false" become JSON booleans in the report
    std::string label;  // the panel's words, from the words files (key "fact.<name>")
    bool shown = true;  // false: for the report and the smoke checks only
    // The words the panel shows before the value: the label, or the name where there is none.
    const std::string& shownLabel() const { return label.empty() ? name : label; }
    // Work spread over frames (done of total): the panel draws a bar, the report writes the value.
    int done = -1, total = 0;
};

// A shown fact's label is the run's words for "fact.<name>" (the lesson's words file, else the app's:
// base/words.hpp), filled with `args` ("levels (of {asked} asked for)"), in the language shown.
class Facts {
public:
    // A fact shown in the panel (as "label: value") and written to the report.
    void add(std::string name, std::string value, const WordArgs& args = {});
    void add(std::string name, const char* value, const WordArgs& args = {}) {
        add(std::move(name), std::string(value), args);
    }
    void add(std::string name, bool value, const WordArgs& args = {});
    // A fact whose label depends on the frame: the words of "fact.<key>" instead of "fact.<name>".
    void addAs(std::string name, std::string_view key, std::string value, const WordArgs& args = {});
    // How far work spread over several frames is ("24 of 64"): a progress bar in the panel.
    void progress(std::string name, int done, int total, const WordArgs& args = {});
    void progressAs(std::string name, std::string_view key, int done, int total, const WordArgs& args = {});
    // A fact for the report and the smoke checks only ("expectErrorsInStep").
    void check(std::string name, std::string value);
    void check(std::string name, const char* value) { check(std::move(name), std::string(value)); }
    void check(std::string name, bool value);

    const std::vector<Fact>& list() const { return facts_; }
    const std::string* find(const std::string& name) const;

private:
    std::vector<Fact> facts_;
};

}  // namespace fx
