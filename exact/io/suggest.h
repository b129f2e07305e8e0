// "Did you mean": the known word closest to a misspelt one, for messages that name the likely fix (an unknown
// scene key, command or option). Only a suggestion for a message: nothing is ever read as the word suggested.
#pragma once

#include <string>
#include <vector>

namespace wrenchkit {

// The word of `known` closest to `word`, compared without case and with '-' read as '_': a known word at
// optimal-string-alignment distance (insertions, deletions, substitutions, adjacent transpositions) at most 1, or
// at most 2 when both words have at least five letters; the first of the closest; "" when none is that close.
std::string closest_word(const std::string& word, const std::vector<std::string>& known);

// " (did you mean \"W\"?)" for the suggestion W, or "" for none.
std::string did_you_mean(const std::string& suggestion);

}  // namespace wrenchkit
