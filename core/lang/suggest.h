#pragma once
// "Did you mean" suggestions from edit distance, for unknown commands, functions, labels and
// variables. A suggestion comes only from names that can stand where the word stands: at the
// start of a statement a command or a keyword that starts statements (never an operator such
// as `not`); in an expression a function where a call stands, else a variable or a constant
// (first the constants that fit the argument the word is); after goto or gosub a label.
// docs/diagnostics.md, "Suggestions".

#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

namespace rb {

class BuiltinTable;
struct Builtin;
namespace ast {
struct Stmt;
}

/// Optimal-string-alignment distance (insert, delete, substitute, swap neighbours).
/// `ignoreCase` compares letters without case.
int editDistance(std::string_view a, std::string_view b, bool ignoreCase);
/// The same, but any distance above `bound` comes back as bound + 1 (and is found sooner).
int editDistance(std::string_view a, std::string_view b, bool ignoreCase, size_t bound);

/// The closest candidate within a distance that grows with the length of `word`, or "" when
/// none is close enough. A candidate equal to `word` apart from case wins outright; of equally
/// close ones, the first that begins with the word's first letter, else the first.
std::string closestMatch(std::string_view word, const std::vector<std::string_view>& candidates,
                         bool ignoreCase);

/// The keywords (lower case) that can begin a statement: `print`, `next`, `endif`, ... (not
/// `and`, `or`, `not`, `mod`, `then`, `to`, `step`, which stand inside one).
const std::vector<std::string_view>& statementKeywords();

/// A command of `builtins` or a keyword that begins statements, close to `word` ("prit" ->
/// "print", "nxt" -> "next"): what the first word of a statement may be.
std::string suggestCommand(const BuiltinTable& builtins, std::string_view word);

/// The constants of `builtins` that fit the parameter `param` of `builtin`: the colours for a
/// colour (`colour`, `background`, `outline`, `fill`), and every constant the built-in's help
/// names (rPen: Down and Up; flip: On and Off; xyText: the fs_ styles).
std::vector<std::string_view> constantsFitting(const BuiltinTable& builtins, const Builtin& builtin,
                                               std::string_view param);

/// A name read in an expression that nothing assigns: the closest of the constants that fit
/// the argument it is (`fitting`, from constantsFitting; first, so they win a tie), the
/// variables assigned in its scope, and the other constants of `builtins`.
std::string suggestValue(std::string_view word, const std::vector<std::string_view>& fitting,
                         const std::vector<std::string_view>& variables, const BuiltinTable& builtins);

/// Adds every name statement `s` uses (variables, arrays, labels, subs and their parameters,
/// what it calls) to `out`, in lower case.
void addNamesOf(const ast::Stmt& s, std::unordered_set<std::string>& out);

/// A name to use instead of the built-in's `name` for a variable, an array or a sub: "myLength"
/// for "length", else "length1", "length2", ...: no built-in's, no keyword, and (in any case)
/// none of `taken` (lower case, as addNamesOf gives them).
std::string freeName(std::string_view name, const BuiltinTable& builtins,
                     const std::unordered_set<std::string>& taken);

}  // namespace rb
