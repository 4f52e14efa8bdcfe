#pragma once
// The scoping rules the compiler and the checker share: where a sub's body ends, which names
// are global in a sub (a leading underscore, and every array), and the names a statement reads
// and writes. The compiler uses them to find a sub's local variables before compiling the sub;
// the checker to find variables that are read but never assigned.

#include <functional>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "lang/ast.h"

namespace rb {
class BuiltinTable;
}

namespace rb::ast {

enum class NameUse { Read, Write, ReadWrite, ArrayWrite };

/// How a sub's body ends.
enum class SubEnd {
  EndSub,     ///< at its endsub (or `end sub`)
  NextSub,    ///< at the next sub
  EndOfFile,  ///< with the file it is written in (an included file's sub never runs on)
};

/// Where a sub lies in the statement list: the `sub` statement at `begin`, its body up to (not
/// including) `end`, which is the endsub, the next sub, the first statement of another file,
/// or the end of the list.
struct SubSpan {
  size_t begin = 0;
  size_t end = 0;
  SubEnd how = SubEnd::EndOfFile;
};

/// Every sub of the program, in order (a sub whose line had a syntax error included).
std::vector<SubSpan> subSpans(const std::vector<Stmt*>& stmts);

/// subSpans() of statements met one at a time: add() each in order, then finish().
class SubSpanFinder {
 public:
  void add(const Stmt& s, size_t index);
  std::vector<SubSpan> finish(size_t count);

 private:
  std::vector<SubSpan> spans_;
  bool open_ = false;
  uint32_t file_ = 0;  ///< the file of the open sub
};

/// `_name` inside a sub is the main program's `name` (and the same variable outside subs).
inline bool isGlobalRef(std::string_view name) { return name.size() > 1 && name[0] == '_'; }
/// The variable a name refers to, without its global marker: "_x" -> "x", "x" -> "x".
inline std::string_view globalName(std::string_view name) {
  return isGlobalRef(name) ? name.substr(1) : name;
}

/// Calls `visit(name, loc, use)` for every variable name in `s` (and the statements of a
/// single-line if). Names of `builtins` are skipped, as are names of called functions. Which
/// arguments of a built-in command are outputs comes from `builtins`; for sub calls (statements
/// and functions in expressions) `isByRefArg(subName, index)` says whether an argument is
/// passed by reference.
void forEachName(const Stmt& s, const BuiltinTable& builtins,
                 const std::function<void(std::string_view, SourceLoc, NameUse)>& visit,
                 const std::function<bool(std::string_view, size_t)>& isByRefArg);

/// The names a program uses as arrays anywhere: `dim name[...]`, `data name; ...` and indexed
/// `name[i]`. Arrays are global (a program by RobotBASIC's authors dims arrays in one sub and
/// reads them in the main program and in another sub): inside a sub, such a name is the global
/// array unless it is one of the sub's parameters.
std::unordered_set<std::string_view> arrayNames(const std::vector<Stmt*>& stmts);
/// Adds the array names of one statement to `out` (arrayNames() one statement at a time).
void addArrayNames(const Stmt& s, std::unordered_set<std::string_view>& out);

}  // namespace rb::ast
