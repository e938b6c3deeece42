#pragma once
// "Did you mean" suggestions for misspelt names (scene keys, CLI commands and flags).
#include <string>
#include <string_view>
#include <vector>

namespace raycast {

/// The optimal-string-alignment distance between a and b: insertions, deletions, substitutions
/// and swaps of two neighbouring characters each cost 1 ("widht" is 1 from "width").
int edit_distance(std::string_view a, std::string_view b);

/// The candidate closest to `word` when it is close enough to be a likely misspelling (at most
/// 2 edits, and fewer edits than the word has characters), else an empty string. Ties go to the
/// first candidate in the list.
std::string nearest_name(std::string_view word, const std::vector<std::string>& candidates);

/// " (did you mean 'x'?)" for the nearest candidate, or "" when none is close.
std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace raycast
