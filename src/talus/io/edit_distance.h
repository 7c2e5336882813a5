#pragma once
// "Did you mean X?" for misspelt keys and enum values.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace talus::io {

// Optimal-string-alignment distance: insertions, deletions, substitutions and swaps of two
// neighbouring characters each cost 1 (a swap is the commonest typo: "nromal").
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `word`, if it is close enough to be a plausible typo: at most
// max(1, min(3, |word| / 4)) edits, so short words need a near-exact match.
std::optional<std::string> closest_match(std::string_view word,
                                         const std::vector<std::string>& candidates);

}  // namespace talus::io
