#pragma once
// "Did you mean" suggestions from edit distance, for unknown commands, functions, labels and
// variables.

#include <string>
#include <string_view>
#include <vector>

namespace rb {

class BuiltinTable;

/// Optimal-string-alignment distance (insert, delete, substitute, swap neighbours).
/// `ignoreCase` compares letters without case.
int editDistance(std::string_view a, std::string_view b, bool ignoreCase);
/// The same, but any distance above `bound` comes back as bound + 1 (and is found sooner).
int editDistance(std::string_view a, std::string_view b, bool ignoreCase, size_t bound);

/// The closest candidate within a distance that grows with the length of `word`, or "" when
/// none is close enough. A candidate equal to `word` apart from case wins outright.
std::string closestMatch(std::string_view word, const std::vector<std::string_view>& candidates,
                         bool ignoreCase);

/// A command of `builtins` or a statement keyword close to `word` ("prit" -> "print").
std::string suggestCommand(const BuiltinTable& builtins, std::string_view word);

}  // namespace rb
