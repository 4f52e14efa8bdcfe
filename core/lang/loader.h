#pragma once
// Loads a program: reads the main file, tokenizes and parses it, and splices in every
// `#include`d file at the point of its directive (each file once). File access goes through a
// SourceReader so that tests can load programs from memory.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lang/ast.h"
#include "lang/ast_walk.h"
#include "lang/compact_ast.h"
#include "base/diagnostic.h"
#include "base/source.h"

namespace rb {

class BuiltinTable;

/// Where program text comes from.
class SourceReader {
 public:
  virtual ~SourceReader() = default;
  /// A canonical name for an existing file (so that one file included twice is seen once), or
  /// nullopt when there is no such file.
  virtual std::optional<std::string> find(const std::string& path) = 0;
  /// The whole text of a file found by find(), or nullopt on a read error.
  virtual std::optional<std::string> read(const std::string& canonical) = 0;
  /// Why a file found by find() may not be included ("" when it may): a reader that confines
  /// what a program reads refuses files outside the folders it allows, and nothing of a refused
  /// file is read.
  virtual std::string refusal(const std::string& /*canonical*/) { return ""; }
};

struct LoadOptions {
  /// Folders searched for an #include that is not found beside the including file.
  std::vector<std::string> libraryDirs;
  /// Keep the statements in their compact form (ast::CompactStmts) instead of as trees: each
  /// statement's tree is freed once parsed, and read back one at a time by whoever walks the
  /// program (`rb check`: a big program's trees take many times the memory of its text). The
  /// compiler and the checks give the same results either way; `stmts` stays empty.
  bool compact = false;
};

/// A label or a sub statement: what the compiler declares before compiling, and the checks
/// read before walking the program.
struct Declaration {
  ast::StmtKind kind = ast::StmtKind::Label;
  bool broken = false;
  std::string_view name;
  SourceLoc loc;
  SourceLoc nameLoc;
  std::vector<ast::Param> params;
};

/// A parsed program with every include spliced in.
struct LoadedProgram {
  explicit LoadedProgram(const BuiltinTable& table) : builtins(table) {}
  /// The built-ins the program was parsed against; it is compiled and checked against them too.
  const BuiltinTable& builtins;
  SourceSet sources;
  ast::Arena arena;
  std::vector<ast::Stmt*> stmts;
  std::unique_ptr<ast::CompactStmts> compact;  ///< set when loaded with LoadOptions::compact
  // Gathered while loading, so that nobody walks the whole program for them again:
  std::vector<Declaration> declarations;  ///< every label and sub statement, in order
  std::vector<ast::SubSpan> subSpans;     ///< ast::subSpans() of the statements
  std::unordered_set<std::string_view> arrays;  ///< ast::arrayNames() of the statements

  /// Reads the statements in order, whichever form they are kept in (see ast::StmtCursor).
  ast::StmtCursor cursor(ast::Arena& scratch) const {
    return compact ? ast::StmtCursor(*compact, scratch) : ast::StmtCursor(stmts);
  }
  size_t stmtCount() const { return compact ? compact->size() : stmts.size(); }
};

/// Loads `text` as the main file named `name` (already read by the caller), against the
/// built-ins of `builtins` (which must outlive the result and what is compiled from it).
/// Diagnostics go to `diags`; the result is usable for checks even when there are errors.
std::unique_ptr<LoadedProgram> loadProgram(const std::string& name, std::string text,
                                           SourceReader& reader, const BuiltinTable& builtins,
                                           const LoadOptions& options, DiagnosticList& diags);

}  // namespace rb
