#pragma once
// One document checked as `rb check` checks a file (load with its includes, compile, lint), and
// what the editor features need from it: the labels and subs of the program with where they
// are, the variables it uses, the files it includes, and for each included file the #include
// line of the document that brought it in.

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "base/diagnostic.h"
#include "lang/loader.h"

namespace rb::lsp {

struct Symbol {
  enum class Kind { Label, Sub };
  Kind kind = Kind::Label;
  std::string name;
  SourceLoc loc;        ///< the name
  SourceLoc end;        ///< subs: the last statement of the body (the sub's line when empty)
  std::vector<std::string> params;  ///< subs: as written, `&` marking by-reference ones
  int container = -1;   ///< labels inside a sub: that sub's index in `symbols`
  /// "sub Name(a, &b)" or "Name:"
  std::string signature() const;
};

struct Analysis {
  std::unique_ptr<LoadedProgram> program;  ///< never null
  DiagnosticList diags;                    ///< sorted, as rb check reports them
  std::vector<Symbol> symbols;             ///< in program order, includes too
  /// One use of a variable: where, and in which scope (the index in `symbols` of the sub whose
  /// body it is in, -1 for the main program).
  struct Use {
    SourceLoc loc;
    int scope = -1;
  };
  /// Every variable name used (exact spelling: names are case-sensitive) and where.
  std::map<std::string, std::vector<Use>> variables;
  /// The names used as arrays anywhere (arrays are global, language.md §5 Subs).
  std::set<std::string> arrays;

  /// The scope (as in Use) of a line of the document (file 0, 1-based line).
  int scopeAt(uint32_t line) const;
  /// Canonical names (as the reader gives them) of every included file.
  std::vector<std::string> includes;
  /// For each source file index: the #include directive in the document (file 0) through which
  /// it was loaded (invalid for file 0, and when it cannot be told).
  std::vector<SourceLoc> includedAt;
};

/// Checks the document `name` with `text` against `builtins`; includes are found through
/// `reader` (which serves open documents before the disk). `portable`: also the warnings of
/// `rb check --portable`.
std::unique_ptr<Analysis> analyze(const std::string& name, const std::string& text,
                                  SourceReader& reader, const BuiltinTable& builtins,
                                  const LoadOptions& options, bool portable = false);

}  // namespace rb::lsp
