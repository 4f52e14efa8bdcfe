#include "lang/lexer.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <unordered_map>

namespace rb {

namespace {

struct Keyword {
  std::string_view word;
  Tok kind;
};

constexpr std::array kKeywords{
    Keyword{"and", Tok::KwAnd},       Keyword{"or", Tok::KwOr},
    Keyword{"not", Tok::KwNot},       Keyword{"mod", Tok::KwMod},
    Keyword{"if", Tok::KwIf},         Keyword{"then", Tok::KwThen},
    Keyword{"else", Tok::KwElse},     Keyword{"elseif", Tok::KwElseIf},
    Keyword{"endif", Tok::KwEndIf},   Keyword{"end", Tok::KwEnd},
    Keyword{"for", Tok::KwFor},       Keyword{"to", Tok::KwTo},
    Keyword{"step", Tok::KwStep},     Keyword{"next", Tok::KwNext},
    Keyword{"while", Tok::KwWhile},   Keyword{"wend", Tok::KwWend},
    Keyword{"repeat", Tok::KwRepeat}, Keyword{"until", Tok::KwUntil},
    Keyword{"break", Tok::KwBreak},   Keyword{"continue", Tok::KwContinue},
    Keyword{"goto", Tok::KwGoto},     Keyword{"gosub", Tok::KwGosub},
    Keyword{"return", Tok::KwReturn}, Keyword{"sub", Tok::KwSub},
    Keyword{"endsub", Tok::KwEndSub}, Keyword{"call", Tok::KwCall},
    Keyword{"dim", Tok::KwDim},       Keyword{"data", Tok::KwData},
    Keyword{"print", Tok::KwPrint},   Keyword{"input", Tok::KwInput},
};

// ASCII letters and digits only (what isalpha/isalnum give in the "C" locale), without a call
// per character.
inline bool isAsciiLetter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
inline bool isIdentStart(char c) { return isAsciiLetter(c) || c == '_'; }
inline bool isIdentChar(char c) {
  return isAsciiLetter(c) || (c >= '0' && c <= '9') || c == '_' || c == '$';
}

class Lexer {
 public:
  Lexer(const SourceSet& sources, uint32_t file, DiagnosticList& diags)
      : text_(sources.file(file).text()), file_(file), diags_(diags) {}

  /// Appends the tokens of the next line to `out`: up to and including its Newline token (a
  /// block comment across lines ends the line too), or, once the text is used up, the final
  /// Newline and then the Eof token alone.
  void line(std::vector<Token>& out) {
    if (done_) {
      push(out, Tok::Eof, pos_, 0);
      return;
    }
    for (;;) {
      if (pos_ >= text_.size()) {
        push(out, Tok::Newline, pos_, 0);
        done_ = true;
        return;
      }
      size_t before = out.size();
      element(out);
      if (out.size() > before && out.back().kind == Tok::Newline) return;
    }
  }

  std::vector<Token> run() {
    std::vector<Token> out;
    out.reserve(text_.size() / 3 + 4);
    while (!done_) line(out);
    line(out);  // Eof
    return out;
  }

 private:
  /// Lexes what starts at pos_ (pos_ < text_.size()): a token, a comment, blanks or a bad
  /// character.
  void element(std::vector<Token>& out) {
    char c = text_[pos_];
    if (c == '\n') {
      push(out, Tok::Newline, pos_, 1);
      ++pos_;
      ++line_;
      lineStart_ = pos_;
      return;
    }
    if (isBlank(c)) {
      do ++pos_;
      while (pos_ < text_.size() && isBlank(text_[pos_]));
      return;
    }
    if (c == '/' && peek(1) == '/') return skipToLineEnd();
    if (c == '\'') return skipToLineEnd();
    if (c == '/' && peek(1) == '*') return blockComment(out);
    if (c == '"') return string(out);
    if (std::isdigit(static_cast<unsigned char>(c)) ||
        (c == '.' && std::isdigit(static_cast<unsigned char>(peek(1)))))
      return number(out);
    if (isIdentStart(c)) return identifier(out);
    if (!op(out)) {
      unsigned char uc = static_cast<unsigned char>(c);
      std::string shown = uc >= 0x20 && uc < 0x7f ? std::string(1, c) : "\\x" + hex(uc);
      diags_.error(loc(pos_), "unexpected character '" + shown + "'", "rb-unexpected-character");
      ++pos_;
    }
  }

 private:
  static std::string hex(unsigned char c) {
    static const char* d = "0123456789abcdef";
    return {d[c >> 4], d[c & 15]};
  }
  char peek(size_t ahead) const {
    return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
  }
  SourceLoc loc(size_t at) const {
    return {file_, line_, static_cast<uint32_t>(at - lineStart_ + 1)};
  }
  void push(std::vector<Token>& out, Tok kind, size_t start, size_t len) {
    Token t;
    t.kind = kind;
    t.loc = loc(start);
    t.text = std::string_view(text_).substr(start, len);
    out.push_back(t);
  }
  static bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
  void skipToLineEnd() {
    const void* nl = std::memchr(text_.data() + pos_, '\n', text_.size() - pos_);
    pos_ = nl ? static_cast<size_t>(static_cast<const char*>(nl) - text_.data()) : text_.size();
  }
  void blockComment(std::vector<Token>& out) {
    SourceLoc startLoc = loc(pos_);
    pos_ += 2;
    bool sawNewline = false;
    while (pos_ < text_.size() && !(text_[pos_] == '*' && peek(1) == '/')) {
      if (text_[pos_] == '\n') {
        if (!sawNewline) push(out, Tok::Newline, pos_, 1);  // the comment ends the statement
        sawNewline = true;
        ++line_;
        lineStart_ = pos_ + 1;
      }
      ++pos_;
    }
    if (pos_ >= text_.size()) {
      diags_.error(startLoc, "unterminated /* comment", "rb-unterminated-comment");
      return;
    }
    pos_ += 2;
  }
  void string(std::vector<Token>& out) {
    size_t start = pos_;
    ++pos_;
    while (pos_ < text_.size() && text_[pos_] != '"' && text_[pos_] != '\n') ++pos_;
    if (pos_ >= text_.size() || text_[pos_] != '"') {
      diags_.error(loc(start), "unterminated string (a string must close on the same line)",
                   "rb-unterminated-string");
      Token t;
      t.kind = Tok::String;
      t.loc = loc(start);
      t.text = std::string_view(text_).substr(start + 1, pos_ - start - 1);
      out.push_back(t);
      return;
    }
    Token t;
    t.kind = Tok::String;
    t.loc = loc(start);
    t.text = std::string_view(text_).substr(start + 1, pos_ - start - 1);
    out.push_back(t);
    ++pos_;
  }
  /// A literal with a two-character prefix (0x, 0%) in the given base, at pos_.
  template <class IsDigit>
  void radixNumber(std::vector<Token>& out, Token t, int base, IsDigit isDigit, const char* what) {
    size_t start = pos_;
    pos_ += 2;
    size_t digits = pos_;
    while (pos_ < text_.size() && isDigit(text_[pos_])) ++pos_;
    uint64_t v = 0;
    auto r = std::from_chars(text_.data() + digits, text_.data() + pos_, v, base);
    if (r.ec != std::errc()) diags_.error(t.loc, std::string(what) + " number too large", "rb-number-too-large");
    t.kind = Tok::Int;
    t.intValue = static_cast<int64_t>(v);
    t.text = std::string_view(text_).substr(start, pos_ - start);
    out.push_back(t);
  }
  void number(std::vector<Token>& out) {
    size_t start = pos_;
    Token t;
    t.loc = loc(start);
    // Hexadecimal 0x1F; binary 0%110101 = 53 (RobotBASIC's course slides). `0 % 2` with
    // spaces, or `x%5`, stays modulo.
    auto isBin = [](char c) { return c == '0' || c == '1'; };
    auto isHex = [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; };
    if (text_[pos_] == '0' && (peek(1) == 'x' || peek(1) == 'X') && isHex(peek(2)))
      return radixNumber(out, t, 16, isHex, "hexadecimal");
    if (text_[pos_] == '0' && peek(1) == '%' && isBin(peek(2)))
      return radixNumber(out, t, 2, isBin, "binary");
    bool isFloat = false;
    while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    if (pos_ < text_.size() && text_[pos_] == '.' ) {
      isFloat = true;
      ++pos_;
      while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    }
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      size_t save = pos_;
      ++pos_;
      if (pos_ < text_.size() && (text_[pos_] == '+' || text_[pos_] == '-')) ++pos_;
      if (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) {
        isFloat = true;
        while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
      } else {
        pos_ = save;  // "2e" is the number 2 followed by the name e
      }
    }
    t.text = std::string_view(text_).substr(start, pos_ - start);
    if (!isFloat) {
      int64_t v = 0;
      auto r = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
      if (r.ec == std::errc()) {
        t.kind = Tok::Int;
        t.intValue = v;
        out.push_back(t);
        return;
      }
      // Too large for a 64-bit integer: keep it as a double.
    }
    std::string digits(t.text);
    t.kind = Tok::Float;
    t.floatValue = std::strtod(digits.c_str(), nullptr);
    if (!std::isfinite(t.floatValue)) {
      diags_.error(t.loc, "number too large: " + digits + " (the largest is about 1.8e308)");
      t.floatValue = 0;
    }
    out.push_back(t);
  }
  void identifier(std::vector<Token>& out) {
    size_t start = pos_;
    while (pos_ < text_.size() && isIdentChar(text_[pos_])) ++pos_;
    std::string_view word = std::string_view(text_).substr(start, pos_ - start);
    char lower[16];
    Tok kind = Tok::Ident;
    if (word.size() < sizeof lower) {
      for (size_t i = 0; i < word.size(); ++i)
        lower[i] = word[i] >= 'A' && word[i] <= 'Z' ? static_cast<char>(word[i] - 'A' + 'a') : word[i];
      std::string_view lw(lower, word.size());
      if (lw == "rem") {  // a remark runs to the end of the line
        skipToLineEnd();
        return;
      }
      kind = keywordKind(lw);
    }
    push(out, kind, start, word.size());
  }
  bool op(std::vector<Token>& out) {
    const OperatorToken t = operatorAt(text_[pos_], peek(1));
    if (t.length == 0) return false;
    push(out, t.kind, pos_, static_cast<size_t>(t.length));
    pos_ += static_cast<size_t>(t.length);
    return true;
  }

  std::string_view text_;  // a view, so that writing pos_ never makes the compiler read it again
  uint32_t file_;
  DiagnosticList& diags_;
  size_t pos_ = 0;
  uint32_t line_ = 1;
  size_t lineStart_ = 0;
  bool done_ = false;  ///< the final Newline was given out
};

}  // namespace

struct LineLexer::Impl {
  Lexer lexer;
};

LineLexer::LineLexer(const SourceSet& sources, uint32_t fileIndex, DiagnosticList& diags)
    : impl_(std::make_unique<Impl>(Impl{Lexer(sources, fileIndex, diags)})) {}

LineLexer::~LineLexer() = default;

void LineLexer::next(std::vector<Token>& out) {
  out.clear();
  impl_->lexer.line(out);
}

std::vector<Token> lex(const SourceSet& sources, uint32_t fileIndex, DiagnosticList& diags) {
  return Lexer(sources, fileIndex, diags).run();
}

Tok keywordKind(std::string_view lowerWord) {
  // The keywords of each length: a word is compared with the few of its own length only.
  constexpr size_t kLongest = 8;
  static const std::array<std::vector<Keyword>, kLongest + 1> byLength = [] {
    std::array<std::vector<Keyword>, kLongest + 1> t;
    for (const auto& k : kKeywords) t.at(k.word.size()).push_back(k);
    return t;
  }();
  if (lowerWord.empty() || lowerWord.size() > kLongest) return Tok::Ident;
  for (const Keyword& k : byLength[lowerWord.size()])
    if (k.word[0] == lowerWord[0] && k.word == lowerWord) return k.kind;
  return Tok::Ident;
}

const std::vector<std::string_view>& keywordSpellings() {
  static const std::vector<std::string_view> words = [] {
    std::vector<std::string_view> w;
    for (const auto& k : kKeywords) w.push_back(k.word);
    w.push_back("rem");
    return w;
  }();
  return words;
}

std::string_view tokName(Tok t) {
  switch (t) {
    case Tok::Eof: return "end of file";
    case Tok::Newline: return "end of line";
    case Tok::Ident: return "a name";
    case Tok::Int: case Tok::Float: return "a number";
    case Tok::String: return "a string";
    case Tok::LParen: return "'('";
    case Tok::RParen: return "')'";
    case Tok::LBracket: return "'['";
    case Tok::RBracket: return "']'";
    case Tok::Comma: return "','";
    case Tok::Semicolon: return "';'";
    case Tok::Colon: return "':'";
    case Tok::Hash: return "'#'";
    case Tok::Plus: return "'+'";
    case Tok::Minus: return "'-'";
    case Tok::Star: return "'*'";
    case Tok::Slash: return "'/'";
    case Tok::Percent: return "'%'";
    case Tok::Caret: return "'^'";
    case Tok::Amp: return "'&'";
    case Tok::Pipe: return "'|'";
    case Tok::Tilde: return "'~'";
    case Tok::Bang: return "'!'";
    case Tok::Shl: return "'<<'";
    case Tok::Shr: return "'>>'";
    case Tok::Assign: return "'='";
    case Tok::EqEq: return "'=='";
    case Tok::NotEq: return "'<>'";
    case Tok::Less: return "'<'";
    case Tok::LessEq: return "'<='";
    case Tok::Greater: return "'>'";
    case Tok::GreaterEq: return "'>='";
    case Tok::AndAnd: return "'&&'";
    case Tok::OrOr: return "'||'";
    case Tok::PlusPlus: return "'++'";
    case Tok::MinusMinus: return "'--'";
    case Tok::PlusAssign: return "'+='";
    case Tok::MinusAssign: return "'-='";
    case Tok::StarAssign: return "'*='";
    case Tok::SlashAssign: return "'/='";
    case Tok::KwAnd: return "'and'";
    case Tok::KwOr: return "'or'";
    case Tok::KwNot: return "'not'";
    case Tok::KwMod: return "'mod'";
    case Tok::KwIf: return "'if'";
    case Tok::KwThen: return "'then'";
    case Tok::KwElse: return "'else'";
    case Tok::KwElseIf: return "'elseif'";
    case Tok::KwEndIf: return "'endif'";
    case Tok::KwEnd: return "'end'";
    case Tok::KwFor: return "'for'";
    case Tok::KwTo: return "'to'";
    case Tok::KwStep: return "'step'";
    case Tok::KwNext: return "'next'";
    case Tok::KwWhile: return "'while'";
    case Tok::KwWend: return "'wend'";
    case Tok::KwRepeat: return "'repeat'";
    case Tok::KwUntil: return "'until'";
    case Tok::KwBreak: return "'break'";
    case Tok::KwContinue: return "'continue'";
    case Tok::KwGoto: return "'goto'";
    case Tok::KwGosub: return "'gosub'";
    case Tok::KwReturn: return "'return'";
    case Tok::KwSub: return "'sub'";
    case Tok::KwEndSub: return "'endsub'";
    case Tok::KwCall: return "'call'";
    case Tok::KwDim: return "'dim'";
    case Tok::KwData: return "'data'";
    case Tok::KwPrint: return "'print'";
    case Tok::KwInput: return "'input'";
  }
  return "a token";
}

}  // namespace rb
