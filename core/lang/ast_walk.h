#pragma once
// Walks the names a statement reads and writes. The compiler uses it to find a sub's local
// variables before compiling the sub; the checker uses it to find variables that are read but
// never assigned.

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

/// Calls `visit(name, loc, use)` for every variable name in `s` (and the statements of a
/// single-line if). Names of `builtins` are skipped, as are names of called functions. Which
/// arguments of a built-in command are outputs comes from `builtins`; for sub calls
/// `isByRefArg(subName, index)` says whether an argument is passed by reference.
void forEachName(const Stmt& s, const BuiltinTable& builtins,
                 const std::function<void(std::string_view, SourceLoc, NameUse)>& visit,
                 const std::function<bool(std::string_view, size_t)>& isByRefArg);

/// The names a program uses as arrays anywhere: `dim name[...]`, `data name; ...` and indexed
/// `name[i]`. Arrays are global (a program by RobotBASIC's authors dims arrays in one sub and
/// reads them in the main program and in another sub): inside a sub, such a name is the global
/// array unless it is one of the sub's parameters.
std::unordered_set<std::string_view> arrayNames(const std::vector<Stmt*>& stmts);

}  // namespace rb::ast
