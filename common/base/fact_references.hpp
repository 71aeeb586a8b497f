#pragma once
// A number a lesson's text quotes from a fact is written as a reference to that fact, so the text
// cannot drift from what the lesson computes: `{fact:NAME}` is the fact's value, `{fact:NAME WORD}`
// the number after WORD in it (the fact "firefly 900, sun 300" gives `{fact:brightestEmitters sun}`
// = 300). The overlay resolves them with the frame's facts, the handout with its run's report.
// GL-free.
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fx {

struct FactReference {
    std::string name;  // the fact's name ("brightestEmitters")
    std::string word;  // empty: the whole value
};

// Every reference in a text, in order.
std::vector<FactReference> factReferences(std::string_view text);

// A fact's value by its name, or nothing.
using FactLookup = std::function<std::optional<std::string>(const std::string& name)>;

// What a reference reads as: the value, or the number after its word; nothing when the fact is
// missing or has no number after the word.
std::optional<std::string> resolveFactReference(const FactReference& reference, const FactLookup& facts);

// The text with every reference replaced by what it reads as; one that does not resolve reads as
// "[NAME?]" (or "[NAME WORD?]"), so a missing fact shows rather than a wrong number.
std::string resolveFactReferences(std::string_view text, const FactLookup& facts);

}  // namespace fx
