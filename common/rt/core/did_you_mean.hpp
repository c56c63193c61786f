// Suggestions for misspelt names: the closest known word by edit distance.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace rt {

// Levenshtein distance: the fewest insertions, deletions and substitutions that turn a into b.
std::size_t edit_distance(std::string_view a, std::string_view b);
// The candidate nearest to `word` if it is at most 2 edits away (a near miss), else nothing.
std::optional<std::string> closest_match(std::string_view word, std::span<const std::string_view> candidates);

}  // namespace rt
