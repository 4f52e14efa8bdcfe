#pragma once
// Tokens of one file -> flat statement list. Syntax errors are collected; after an error the
// parser skips to the end of the line and goes on, so one run reports every bad line.

#include <functional>
#include <vector>

#include "lang/ast.h"
#include "base/diagnostic.h"
#include "lang/token.h"

namespace rb {

class BuiltinTable;

/// Parses one file's tokens. `#include` lines become StmtKind::Include entries. `builtins`
/// says which names are commands (and how their arguments are written).
std::vector<ast::Stmt*> parseTokens(const std::vector<Token>& tokens, ast::Arena& arena,
                                    const BuiltinTable& builtins, DiagnosticList& diags);

/// Lexes and parses `sources.file(fileIndex)` line by line: the same statements and
/// diagnostics as parseTokens(lex(...)), without ever holding the whole file's tokens.
std::vector<ast::Stmt*> parseFile(const SourceSet& sources, uint32_t fileIndex, ast::Arena& arena,
                                  const BuiltinTable& builtins, DiagnosticList& diags);

/// The same, handing the statements of each line to `onLine` as soon as the line is parsed
/// (nothing of a line is kept by the parser after that: `arena` may be reset in `onLine`).
void parseFileLines(const SourceSet& sources, uint32_t fileIndex, ast::Arena& arena,
                    const BuiltinTable& builtins, DiagnosticList& diags,
                    const std::function<void(const std::vector<ast::Stmt*>&)>& onLine);

/// Parses `sources.file(fileIndex)` as one expression on its first line, as a debugger's watch
/// is written (`x * 2`, `a[3] + 1`, `left(s, 2)`): nullptr, with the syntax error in `diags`,
/// when the line is empty, is no expression, or holds more than one.
ast::Expr* parseExpression(const SourceSet& sources, uint32_t fileIndex, ast::Arena& arena,
                           const BuiltinTable& builtins, DiagnosticList& diags);

/// The binary operator table: precedence (higher binds tighter, 0 = not a binary operator) and
/// associativity. Unary operators bind tighter than every binary one.
struct BinaryOpInfo {
  int prec;
  bool rightAssoc;
};
BinaryOpInfo binaryOpInfo(Tok t);

}  // namespace rb
