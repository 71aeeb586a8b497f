#pragma once
// Deterministic ways to break a JSON document: every value deleted or replaced by a wrong type or an
// extreme number (a fixed share of them, chosen by position so each run makes the same set), the text
// cut short, invalid UTF-8 and NUL bytes put in, and for glTF files hostile counts, offsets, strides
// and indices on every accessor and buffer view.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace mutation {

struct Mutant {
    std::string what;  // "delete /objects/2/transform", "truncate at 812"
    std::string text;
};

// Tree mutations: for each value, `perValue` of the replacements (rotating through the list by the
// value's position, so every replacement meets many fields).
std::vector<Mutant> treeMutations(const nlohmann::json& document, int perValue);

// Text mutations: `cuts` truncations spread over the text, invalid UTF-8 and NUL bytes at `inserts`
// positions.
std::vector<Mutant> textMutations(const std::string& text, int cuts, int inserts);

// glTF mutations: hostile numbers on every accessor, buffer view, sampler and skin field that indexes
// or sizes data.
std::vector<Mutant> gltfMutations(const nlohmann::json& document);

}  // namespace mutation
