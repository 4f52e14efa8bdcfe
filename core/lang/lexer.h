#pragma once
// Turns one source file into tokens. Comments (//, ', rem, /* */) are dropped; each line end is
// a Newline token, so statements are line-based.

#include <memory>
#include <vector>

#include "base/diagnostic.h"
#include "lang/token.h"

namespace rb {

/// An operator or punctuation token that starts with `c` (followed by `n`): its kind and its
/// length, 1 or 2; length 0 when `c` starts none. The lexer's rule, which rb test
/// --similarity's quick scan (grade/similarity.cpp) reads by too. ('/' is here as a division;
/// the callers look for the comments it may start first.)
struct OperatorToken {
  Tok kind;
  int length;
};
constexpr OperatorToken operatorAt(char c, char n) {
  switch (c) {
    case '(': return {Tok::LParen, 1};
    case ')': return {Tok::RParen, 1};
    case '[': return {Tok::LBracket, 1};
    case ']': return {Tok::RBracket, 1};
    case ',': return {Tok::Comma, 1};
    case ';': return {Tok::Semicolon, 1};
    case ':': return {Tok::Colon, 1};
    case '#': return {Tok::Hash, 1};
    case '%': return {Tok::Percent, 1};
    case '^': return {Tok::Caret, 1};
    case '~': return {Tok::Tilde, 1};
    case '+': return n == '+' ? OperatorToken{Tok::PlusPlus, 2} : n == '=' ? OperatorToken{Tok::PlusAssign, 2} : OperatorToken{Tok::Plus, 1};
    case '-': return n == '-' ? OperatorToken{Tok::MinusMinus, 2} : n == '=' ? OperatorToken{Tok::MinusAssign, 2} : OperatorToken{Tok::Minus, 1};
    case '*': return n == '=' ? OperatorToken{Tok::StarAssign, 2} : OperatorToken{Tok::Star, 1};
    case '/': return n == '=' ? OperatorToken{Tok::SlashAssign, 2} : OperatorToken{Tok::Slash, 1};
    case '&': return n == '&' ? OperatorToken{Tok::AndAnd, 2} : OperatorToken{Tok::Amp, 1};
    case '|': return n == '|' ? OperatorToken{Tok::OrOr, 2} : OperatorToken{Tok::Pipe, 1};
    case '!': return n == '=' ? OperatorToken{Tok::NotEq, 2} : OperatorToken{Tok::Bang, 1};
    case '=': return n == '=' ? OperatorToken{Tok::EqEq, 2} : OperatorToken{Tok::Assign, 1};
    case '<':
      return n == '>' ? OperatorToken{Tok::NotEq, 2}
             : n == '=' ? OperatorToken{Tok::LessEq, 2}
             : n == '<' ? OperatorToken{Tok::Shl, 2}
                        : OperatorToken{Tok::Less, 1};
    case '>':
      return n == '=' ? OperatorToken{Tok::GreaterEq, 2} : n == '>' ? OperatorToken{Tok::Shr, 2} : OperatorToken{Tok::Greater, 1};
    default: return {Tok::Eof, 0};
  }
}

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
