#pragma once
// Turns one source file into tokens. Comments (//, ', rem, /* */) are dropped; each line end is
// a Newline token, so statements are line-based.

#include <memory>
#include <vector>

#include "base/diagnostic.h"
#include "lang/token.h"

namespace rb {

/// Tokenizes `sources.file(fileIndex)`. Lexical errors go to `diags`; the bad characters are
/// skipped so that parsing can go on.
std::vector<Token> lex(const SourceSet& sources, uint32_t fileIndex, DiagnosticList& diags);

/// The same tokens as lex(), one line at a time, so that a parser holds only the line it is
/// reading (a program's tokens take several times the memory of its text).
class LineLexer {
 public:
  LineLexer(const SourceSet& sources, uint32_t fileIndex, DiagnosticList& diags);
  ~LineLexer();
  LineLexer(const LineLexer&) = delete;
  LineLexer& operator=(const LineLexer&) = delete;
  /// Replaces `out` with the next line's tokens, up to and including its Newline (a block
  /// comment that spans lines ends the line at its first line end); after the last line, the
  /// Eof token alone. Lexical errors of those characters go to the diagnostics as they are met.
  void next(std::vector<Token>& out);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rb
