#pragma once
// Suggestions for misspelt names ("emisive" -> "emissive") in unknown-field warnings and enum errors.
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace fx {

// Edits (insert, delete, substitute, swap two neighbours) that turn `a` into `b`, ignoring ASCII case.
std::size_t editDistance(std::string_view a, std::string_view b);

// The candidate nearest to `word`, when it is near enough to be a likely typo: at most a third of the
// word's letters wrong (at least one). Ties go to the earlier candidate.
std::optional<std::string> closestName(std::string_view word, std::span<const std::string> candidates);

}  // namespace fx
