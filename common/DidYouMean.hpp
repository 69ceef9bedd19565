#pragma once
// Spelling suggestions for unknown names ("did you mean ...?").

#include <string>
#include <vector>

namespace fsi::common {

/// Edit (Levenshtein) distance between two strings.
std::size_t edit_distance(const std::string &a, const std::string &b);

/// The closest candidate to `word`, or "" when none is close enough to be a likely typo.
std::string closest_match(const std::string &word, const std::vector<std::string> &candidates);

/// " Did you mean 'x'?" or "", ready to append to an error message.
std::string did_you_mean(const std::string &word, const std::vector<std::string> &candidates);

/// "a, b, c": the candidates joined for an error message.
std::string join(const std::vector<std::string> &items, const std::string &separator = ", ");

} // namespace fsi::common
