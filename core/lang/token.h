#pragma once
// Token kinds of RobotBASIC. Keywords are case-insensitive; identifiers keep their case.

#include <cstdint>
#include <string_view>
#include <vector>

#include "base/source.h"

namespace rb {

enum class Tok : uint8_t {
  Eof,
  Newline,
  Ident,
  Int,
  Float,
  String,
  // punctuation and operators
  LParen, RParen, LBracket, RBracket, Comma, Semicolon, Colon, Hash,
  Plus, Minus, Star, Slash, Percent, Caret, Amp, Pipe, Tilde, Bang,
  Shl, Shr, Assign /* = */, EqEq, NotEq, Less, LessEq, Greater, GreaterEq, AndAnd, OrOr,
  PlusPlus, MinusMinus, PlusAssign, MinusAssign, StarAssign, SlashAssign,
  // keywords
  KwAnd, KwOr, KwNot, KwMod,
  KwIf, KwThen, KwElse, KwElseIf, KwEndIf, KwEnd,
  KwFor, KwTo, KwStep, KwNext, KwWhile, KwWend, KwRepeat, KwUntil, KwBreak, KwContinue,
  KwGoto, KwGosub, KwReturn, KwSub, KwEndSub, KwCall, KwDim, KwData, KwPrint, KwInput,
};

struct Token {
  Tok kind = Tok::Eof;
  SourceLoc loc;
  std::string_view text;  ///< the token's characters in the source (string: without quotes)
  int64_t intValue = 0;    ///< for Int
  double floatValue = 0;   ///< for Float
};

/// A readable name for a token kind, for messages ("end of line", "')'").
std::string_view tokName(Tok t);
/// The keyword a lower-case word spells, or Tok::Ident.
Tok keywordKind(std::string_view lowerWord);
/// Every keyword spelling (lower case), for "did you mean" and the docs.
const std::vector<std::string_view>& keywordSpellings();

}  // namespace rb
