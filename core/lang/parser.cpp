#include "lang/parser.h"

#include <cctype>
#include <optional>
#include <string>
#include <utility>

#include "lang/abandon.h"
#include "lang/builtins.h"
#include "lang/lexer.h"
#include "lang/suggest.h"

namespace rb {

using ast::Expr;
using ast::ExprKind;
using ast::Stmt;
using ast::StmtKind;

BinaryOpInfo binaryOpInfo(Tok t) {
  // Precedence, low to high: or; and; comparisons; |; &; << >>; + -; * / % mod; ^ (right).
  switch (t) {
    case Tok::KwOr: case Tok::OrOr: return {1, false};
    case Tok::KwAnd: case Tok::AndAnd: return {2, false};
    case Tok::Assign: case Tok::EqEq: case Tok::NotEq: case Tok::Less: case Tok::LessEq:
    case Tok::Greater: case Tok::GreaterEq: return {3, false};
    case Tok::Pipe: return {4, false};
    case Tok::Amp: return {5, false};
    case Tok::Shl: case Tok::Shr: return {6, false};
    case Tok::Plus: case Tok::Minus: return {7, false};
    case Tok::Star: case Tok::Slash: case Tok::Percent: case Tok::KwMod: return {8, false};
    case Tok::Caret: return {9, true};
    default: return {0, false};
  }
}

namespace {

constexpr int kMaxNesting = 200;
/// The deepest expression tree: nesting plus operators chained at one level (`1+1+1...` is a
/// tree as deep as it is long, and the compiler and checker walk it recursively).
constexpr int kMaxTreeDepth = 1000;

/// 'text' (built by appending: GCC 12 warns falsely about operator+ chains of this shape).
std::string quoted(std::string_view text, char quote = '\'') {
  std::string out;
  out.reserve(text.size() + 2);
  out += quote;
  out += text;
  out += quote;
  return out;
}

/// Where the parser's tokens come from, one line at a time (see LineLexer::next).
class TokenLines {
 public:
  virtual ~TokenLines() = default;
  virtual void next(std::vector<Token>& out) = 0;
};

/// Straight from the source text: only one line's tokens exist at a time.
class LexedLines : public TokenLines {
 public:
  LexedLines(const SourceSet& sources, uint32_t file, DiagnosticList& diags)
      : lexer_(sources, file, diags) {}
  void next(std::vector<Token>& out) override { lexer_.next(out); }

 private:
  LineLexer lexer_;
};

/// From tokens lexed beforehand, cut at each Newline.
class TokenVectorLines : public TokenLines {
 public:
  explicit TokenVectorLines(const std::vector<Token>& toks) : toks_(toks) {}
  void next(std::vector<Token>& out) override {
    out.clear();
    while (i_ < toks_.size()) {
      out.push_back(toks_[i_++]);
      if (out.back().kind == Tok::Newline || out.back().kind == Tok::Eof) return;
    }
    Token eof;
    if (!toks_.empty()) eof.loc = toks_.back().loc;
    out.push_back(eof);
  }

 private:
  const std::vector<Token>& toks_;
  size_t i_ = 0;
};

class Parser {
 public:
  Parser(TokenLines& lines, ast::Arena& arena, const BuiltinTable& builtins,
         DiagnosticList& diags)
      : lines_(lines), arena_(arena), builtins_(builtins), diags_(diags) {}

  /// Parses line by line: toks_ holds the tokens of one line, ending with its Newline (or the
  /// Eof); nothing in a statement looks past its line.
  std::vector<Stmt*> run() {
    std::vector<Stmt*> out;
    run([&](const std::vector<Stmt*>& line) { out.insert(out.end(), line.begin(), line.end()); });
    return out;
  }

  /// The first line as one expression (parseExpression): the expression, or nullptr after
  /// reporting why it is none.
  Expr* expressionLine() {
    lines_.next(toks_);
    pos_ = 0;
    try {
      if (atLineEnd()) failHere("an expression");
      Expr* e = expression();
      if (!atLineEnd()) {
        std::string shown =
            cur().kind == Tok::String ? quoted(cur().text, '"') : quoted(cur().text);
        fail(cur().loc, "unexpected " + shown + " after the end of the expression");
      }
      return e;
    } catch (const StatementAbandoned&) {
      return nullptr;
    }
  }

  /// Hands each line's statements to `onLine`, then forgets them.
  void run(const std::function<void(const std::vector<Stmt*>&)>& onLine) {
    std::vector<Stmt*> out;  // the statements of one line
    for (;;) {
      lines_.next(toks_);
      pos_ = 0;
      items_.clear();  // what an abandoned line left
      if (cur().kind == Tok::Eof) break;
      if (cur().kind == Tok::Newline) continue;
      try {
        line(out);
      } catch (const StatementAbandoned&) {
        keepBlockOpener(0, out);
        while (cur().kind != Tok::Newline && cur().kind != Tok::Eof) ++pos_;
      }
      if (!out.empty()) onLine(out);
      out.clear();
      if (cur().kind == Tok::Eof || diags_.capped()) break;
    }
  }

 private:
  /// After a syntax error in a line that opens a block (for, while, repeat, a block if, sub) or
  /// closes one with a condition (until), keeps a placeholder so that the blocks still pair
  /// and no second, misleading error is reported.
  ///
  /// A misspelt closer (`nxt`, reported as an unknown command with "did you mean 'next'?") is
  /// kept the same way, as a broken closer with the word in `name`: the compiler lets it close
  /// the block it would close, and that block is not reported again as unclosed.
  void keepBlockOpener(size_t start, std::vector<Stmt*>& out) {
    size_t i = start;
    if (toks_[i].kind == Tok::Ident && toks_[i + 1].kind == Tok::Colon) i += 2;  // a label
    std::optional<GuessedCloser> closer = std::exchange(guessedCloser_, std::nullopt);
    if (closer && closer->loc == toks_[i].loc) {  // the line's statement, not a single-line if's
      Stmt* s = newStmt(closer->kind, toks_[i].loc);
      s->broken = true;
      s->name = toks_[i].text;
      s->nameLoc = toks_[i].loc;
      out.push_back(s);
      return;
    }
    StmtKind kind;
    switch (toks_[i].kind) {
      case Tok::KwFor: kind = StmtKind::For; break;
      case Tok::KwWhile: kind = StmtKind::While; break;
      case Tok::KwRepeat: kind = StmtKind::Repeat; break;
      case Tok::KwSub: kind = StmtKind::Sub; break;
      case Tok::KwUntil: kind = StmtKind::Until; break;
      case Tok::KwIf: {
        // A block if has nothing after "then" (or no "then"); a single-line if closes itself.
        size_t j = i + 1;
        while (toks_[j].kind != Tok::Newline && toks_[j].kind != Tok::Eof && toks_[j].kind != Tok::KwThen) ++j;
        if (toks_[j].kind == Tok::KwThen && toks_[j + 1].kind != Tok::Newline && toks_[j + 1].kind != Tok::Eof)
          return;
        kind = StmtKind::If;
        break;
      }
      default: return;
    }
    if (!out.empty() && out.back()->loc == toks_[i].loc) return;  // already added
    Stmt* s = newStmt(kind, toks_[i].loc);
    s->broken = true;
    out.push_back(s);
  }

  const Token& cur() const { return toks_[pos_]; }
  const Token& peek(size_t n = 1) const {
    size_t i = pos_ + n;
    return i < toks_.size() ? toks_[i] : toks_.back();
  }
  bool at(Tok k) const { return cur().kind == k; }
  bool atLineEnd() const { return at(Tok::Newline) || at(Tok::Eof); }
  const Token& advance() { return toks_[pos_++]; }
  bool accept(Tok k) {
    if (!at(k)) return false;
    ++pos_;
    return true;
  }

  [[noreturn]] void fail(SourceLoc loc, std::string message, const char* code = "rb-syntax",
                         std::string suggestion = {}, size_t length = 0) {
    std::optional<FixIt> fix;
    if (!suggestion.empty() && length > 0)
      fix = FixIt{loc, {loc.file, loc.line, static_cast<uint32_t>(loc.col + length)}, std::move(suggestion)};
    failWithFix(loc, {}, std::move(message), code, std::move(fix));
  }
  /// The same with the range's last character (`end`, invalid: the word at loc) and any fix-it.
  [[noreturn]] void failWithFix(SourceLoc loc, SourceLoc end, std::string message, const char* code,
                                std::optional<FixIt> fix) {
    // One error per line: a lexical error already explains what follows it.
    if (!diags_.hasErrorOnLine(loc.file, loc.line)) {
      Diagnostic& d = diags_.error(loc, std::move(message), code);
      d.end = end;
      if (fix) d.fixits.push_back(std::move(*fix));
    }
    throw StatementAbandoned{};
  }
  /// One level of nesting (a parenthesis, an operator's operand, a single-line if's
  /// statements) while it lives. The count goes down however the level is left, also when a
  /// syntax error unwinds through it, so an error on one line leaves no depth behind for the
  /// next.
  class Nested {
   public:
    Nested(Parser& p, SourceLoc loc) : p_(p) {
      if (p_.depth_ >= kMaxNesting) p_.fail(loc, "expression nested too deeply", "rb-nesting-too-deep");
      p_.deepen(loc);
      ++p_.depth_;
    }
    ~Nested() {
      --p_.depth_;
      --p_.treeDepth_;
    }
    Nested(const Nested&) = delete;
    Nested& operator=(const Nested&) = delete;

   private:
    Parser& p_;
  };
  /// One more level of the expression tree (a nesting, or an operator chained to the left).
  void deepen(SourceLoc loc) {
    if (treeDepth_ >= kMaxTreeDepth)
      fail(loc, "expression too long (more than " + std::to_string(kMaxTreeDepth) +
                    " operators or nested parts in one expression)",
           "rb-nesting-too-deep");
    ++treeDepth_;
  }
  /// Runs `parse` one level deeper.
  template <typename F>
  auto nested(SourceLoc loc, F parse) {
    Nested level(*this, loc);
    return parse();
  }

  [[noreturn]] void failHere(const std::string& expected) {
    std::string found(tokName(cur().kind));
    if (cur().kind == Tok::Ident) found = quoted(cur().text);
    fail(cur().loc, "expected " + expected + ", found " + found);
  }
  const Token& expect(Tok k, const std::string& what) {
    if (!at(k)) failHere(what);
    return advance();
  }
  void expectLineEnd() {
    if (!atLineEnd()) {
      std::string shown = cur().kind == Tok::String ? quoted(cur().text, '"') : quoted(cur().text);
      fail(cur().loc, "unexpected " + shown + " after the end of the statement");
    }
  }

  /// Where a value stands whose end may be followed by a second value (rb-missing-operator).
  enum class Place {
    Value,         ///< an assignment's or a return's value
    PrintItem,     ///< an item of print
    ListArgument,  ///< an item of a command that takes a print list (xyString x, y, ...)
  };

  /// Two values side by side, as beginners write them (`print "moves: " n`, `total = 2 n`):
  /// after the value that just ended, the current token starts another one. Reports which
  /// operator or separator is missing, with a fix-it that inserts it (rb-missing-operator);
  /// returns when the line goes on otherwise (a separator, `then`, `else`, an operator, the end).
  void noValuesSideBySide(Place place) {
    if (pos_ == 0 || !atValueStart()) return;
    size_t leftLast = pos_ - 1;
    size_t leftFirst = valueStartBefore(leftLast);
    size_t rightLast = valueEndFrom(pos_);
    bool text = holdsString(leftFirst, leftLast) || holdsString(pos_, rightLast);
    Tok before = toks_[leftLast].kind;
    Tok after = cur().kind;
    // In print, '+' joins text as ',' does; two numbers printed side by side want ',' (with
    // '+' they would be added). A print-list command's first items are coordinates: ','. A
    // number or a parenthesis before a name or a parenthesis is a product, as algebra writes
    // 2n and (a + b)c.
    std::string_view op = "+";
    if (place == Place::ListArgument || (place == Place::PrintItem && !text)) {
      op = ",";
    } else if (!text && (before == Tok::Int || before == Tok::Float || before == Tok::RParen) &&
               (after == Tok::Ident || after == Tok::LParen)) {
      op = "*";
    }
    SourceLoc at = tokenEnd(toks_[leftLast]);
    ++at.col;  // right after the first value
    std::string insert(op == "," ? "" : " ");
    insert += op;
    if (cur().loc.col <= at.col) insert += ' ';  // nothing between the values
    // Built by appending (see quoted()).
    std::string message = "missing ";
    message += quoted(op);
    message += " between ";
    message += shownValue(leftFirst, leftLast);
    message += " and ";
    message += shownValue(pos_, rightLast);
    failWithFix(cur().loc, tokenEnd(toks_[rightLast]), std::move(message), "rb-missing-operator",
                FixIt{at, at, std::move(insert)});
  }

  /// True when the current token can only begin a value here: a number, a string, '(' or a
  /// name that is not a command (a command starts a statement: `x = 1 rForward 10` is two
  /// statements on one line, no sum) nor a label's (`name:`).
  bool atValueStart() const {
    switch (cur().kind) {
      case Tok::Int: case Tok::Float: case Tok::String: case Tok::LParen: return true;
      case Tok::Ident:
        return peek().kind != Tok::Colon && !builtins_.find(cur().text, BuiltinKind::Command);
      default: return false;
    }
  }

  static bool isOpen(Tok k) { return k == Tok::LParen || k == Tok::LBracket; }
  static bool isClose(Tok k) { return k == Tok::RParen || k == Tok::RBracket; }

  /// The first token of the value whose last token is toks_[last]: a parenthesised group with
  /// the name before it (a call, an index), or the token alone.
  size_t valueStartBefore(size_t last) const {
    if (!isClose(toks_[last].kind)) return last;
    int depth = 0;
    for (size_t i = last + 1; i-- > 0;) {
      if (isClose(toks_[i].kind)) ++depth;
      if (isOpen(toks_[i].kind) && --depth == 0)
        return i > 0 && toks_[i - 1].kind == Tok::Ident ? i - 1 : i;
    }
    return last;
  }

  /// The last token of the value that starts at toks_[first] (see valueStartBefore); when its
  /// parenthesis is not closed on the line, the first token alone.
  size_t valueEndFrom(size_t first) const {
    size_t i = first;
    if (toks_[i].kind == Tok::Ident && isOpen(toks_[i + 1].kind)) ++i;
    if (!isOpen(toks_[i].kind)) return first;
    int depth = 0;
    for (; toks_[i].kind != Tok::Newline && toks_[i].kind != Tok::Eof; ++i) {
      if (isOpen(toks_[i].kind)) ++depth;
      if (isClose(toks_[i].kind) && --depth == 0) return i;
    }
    return first;
  }

  bool holdsString(size_t first, size_t last) const {
    for (size_t i = first; i <= last; ++i)
      if (toks_[i].kind == Tok::String) return true;
    return false;
  }

  /// Tokens [first, last] as the message shows them: a string in its double quotes, anything
  /// else in single quotes, written as in the source (one space where it has any); cut after
  /// about 40 bytes.
  std::string shownValue(size_t first, size_t last) const {
    std::string text;
    for (size_t i = first; i <= last; ++i) {
      const Token& t = toks_[i];
      if (i > first && t.loc.col > tokenEnd(toks_[i - 1]).col + 1) text += ' ';
      if (t.kind == Tok::String) text += quoted(t.text, '"');
      else text += t.text;
    }
    constexpr size_t kLongest = 40;
    if (text.size() > kLongest) {
      size_t cut = kLongest - 3;
      while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // whole characters
      bool inString = first == last && toks_[first].kind == Tok::String;
      text.resize(cut);
      text += inString ? "...\"" : "...";
    }
    return first == last && toks_[first].kind == Tok::String ? text : quoted(text);
  }

  // line -> [label ':'] [statement] NEWLINE  |  '#' include STRING NEWLINE
  void line(std::vector<Stmt*>& out) {
    if (at(Tok::Hash)) {
      Stmt* s = arena_.stmt();
      s->kind = StmtKind::Include;
      s->loc = cur().loc;
      ++pos_;
      if (!at(Tok::Ident) || lower(cur().text) != "include")
        fail(cur().loc, "unknown directive: only #include is supported", "rb-unknown-directive");
      ++pos_;
      const Token& file = expect(Tok::String, "a file name in quotes after #include");
      s->name = file.text;
      s->nameLoc = file.loc;
      expectLineEnd();
      out.push_back(s);
      return;
    }
    if (at(Tok::Ident) && peek().kind == Tok::Colon) {
      Stmt* s = arena_.stmt();
      s->kind = StmtKind::Label;
      s->loc = s->nameLoc = cur().loc;
      s->name = cur().text;
      pos_ += 2;
      out.push_back(s);
      if (atLineEnd()) return;
    }
    out.push_back(statement(false));
    expectLineEnd();
  }

  Stmt* newStmt(StmtKind kind, SourceLoc loc) {
    Stmt* s = arena_.stmt();
    s->kind = kind;
    s->loc = loc;
    return s;
  }

  // statement -> keyword statement | assignment | command | sub call
  Stmt* statement(bool inLineIf) {
    const Token& t = cur();
    SourceLoc loc = t.loc;
    switch (t.kind) {
      case Tok::KwPrint: {
        ++pos_;
        Stmt* s = newStmt(StmtKind::Print, loc);
        printList(s);
        return s;
      }
      case Tok::KwInput: return inputStmt();
      case Tok::KwIf: return ifStmt(inLineIf);
      case Tok::KwElseIf: {
        ++pos_;
        noBlockInLineIf(inLineIf, loc, "elseif");
        Stmt* s = newStmt(StmtKind::ElseIf, loc);
        s->value = expression();
        accept(Tok::KwThen);
        return s;
      }
      case Tok::KwElse: {
        ++pos_;
        noBlockInLineIf(inLineIf, loc, "else");
        if (at(Tok::KwIf)) {  // "else if cond" is read as elseif
          ++pos_;
          Stmt* s = newStmt(StmtKind::ElseIf, loc);
          s->value = expression();
          accept(Tok::KwThen);
          return s;
        }
        return newStmt(StmtKind::Else, loc);
      }
      case Tok::KwEndIf:
        ++pos_;
        noBlockInLineIf(inLineIf, loc, "endif");
        return newStmt(StmtKind::EndIf, loc);
      case Tok::KwEnd:
        ++pos_;
        if (accept(Tok::KwIf)) {
          noBlockInLineIf(inLineIf, loc, "end if");
          return newStmt(StmtKind::EndIf, loc);
        }
        if (accept(Tok::KwSub)) {
          noBlockInLineIf(inLineIf, loc, "end sub");
          return newStmt(StmtKind::EndSub, loc);
        }
        return newStmt(StmtKind::End, loc);
      case Tok::KwFor: return forStmt(inLineIf);
      case Tok::KwNext: {
        ++pos_;
        noBlockInLineIf(inLineIf, loc, "next");
        Stmt* s = newStmt(StmtKind::Next, loc);
        if (at(Tok::Ident)) {
          s->name = cur().text;
          s->nameLoc = cur().loc;
          ++pos_;
        }
        return s;
      }
      case Tok::KwWhile: {
        ++pos_;
        noBlockInLineIf(inLineIf, loc, "while");
        Stmt* s = newStmt(StmtKind::While, loc);
        s->value = expression();
        return s;
      }
      case Tok::KwWend:
        ++pos_;
        noBlockInLineIf(inLineIf, loc, "wend");
        return newStmt(StmtKind::Wend, loc);
      case Tok::KwRepeat:
        ++pos_;
        noBlockInLineIf(inLineIf, loc, "repeat");
        return newStmt(StmtKind::Repeat, loc);
      case Tok::KwUntil: {
        ++pos_;
        noBlockInLineIf(inLineIf, loc, "until");
        Stmt* s = newStmt(StmtKind::Until, loc);
        s->value = expression();
        return s;
      }
      case Tok::KwBreak: ++pos_; return newStmt(StmtKind::Break, loc);
      case Tok::KwContinue: ++pos_; return newStmt(StmtKind::Continue, loc);
      case Tok::KwGoto:
      case Tok::KwGosub: {
        ++pos_;
        Stmt* s = newStmt(t.kind == Tok::KwGoto ? StmtKind::Goto : StmtKind::Gosub, loc);
        const Token& name = expect(Tok::Ident, "a label name");
        s->name = name.text;
        s->nameLoc = name.loc;
        return s;
      }
      case Tok::KwReturn: {
        ++pos_;
        Stmt* s = newStmt(StmtKind::Return, loc);
        if (!atLineEnd() && !at(Tok::KwElse)) {
          s->value = expression();
          noValuesSideBySide(Place::Value);
        }
        return s;
      }
      case Tok::KwSub: return subStmt(inLineIf);
      case Tok::KwEndSub:
        ++pos_;
        noBlockInLineIf(inLineIf, loc, "endsub");
        return newStmt(StmtKind::EndSub, loc);
      case Tok::KwCall: {
        ++pos_;
        Stmt* s = newStmt(StmtKind::Call, loc);
        const Token& name = expect(Tok::Ident, "a sub name after call");
        s->name = name.text;
        s->nameLoc = name.loc;
        if (accept(Tok::LParen)) {
          s->paren = true;
          if (!at(Tok::RParen)) argList(s->exprs);
          expect(Tok::RParen, "')' to close the argument list");
        } else if (!atLineEnd() && !at(Tok::KwElse)) {
          argList(s->exprs);
        }
        return s;
      }
      case Tok::KwDim: return dimStmt();
      case Tok::KwData: return dataStmt();
      case Tok::Ident: return identStmt();
      default: break;
    }
    failHere("a statement");
  }

  void noBlockInLineIf(bool inLineIf, SourceLoc loc, const char* what) {
    if (inLineIf)
      fail(loc, std::string("'") + what + "' cannot be part of a single-line if (put it on its own line)",
           "rb-block-in-line-if");
  }

  static std::string lower(std::string_view s) {
    std::string r(s);
    for (char& c : r) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return r;
  }

  // print-list -> [ expr { (',' | ';') expr } [',' | ';'] ]
  void printList(Stmt* s) {
    Place place = s->kind == StmtKind::Print ? Place::PrintItem : Place::ListArgument;
    while (!atLineEnd() && !at(Tok::KwElse)) {
      s->exprs.push_back(expression());
      if (at(Tok::Comma) || at(Tok::Semicolon)) {
        s->seps.push_back(advance().kind);
      } else {
        noValuesSideBySide(place);
        s->seps.push_back(Tok::Eof);
        break;
      }
    }
    s->exprs.shrink_to_fit();
    s->seps.shrink_to_fit();
  }

  // input -> INPUT [prompt (',' | ';')] lvalue
  Stmt* inputStmt() {
    Stmt* s = newStmt(StmtKind::Input, cur().loc);
    ++pos_;
    Expr* first = expression();
    if (at(Tok::Comma) || at(Tok::Semicolon)) {
      ++pos_;
      s->value = first;
      s->target = lvalue();
    } else {
      if (first->kind != ExprKind::Var && first->kind != ExprKind::Index)
        fail(first->loc, "input needs a variable to store what is typed");
      s->target = first;
    }
    return s;
  }

  // if -> IF expr NEWLINE                      (block)
  //     | IF expr THEN NEWLINE                 (block)
  //     | IF expr THEN statement [ELSE statement]
  Stmt* ifStmt(bool inLineIf) {
    SourceLoc loc = cur().loc;
    ++pos_;
    Expr* cond = expression();
    bool then = accept(Tok::KwThen);
    if (atLineEnd()) {
      noBlockInLineIf(inLineIf, loc, "if");
      Stmt* s = newStmt(StmtKind::If, loc);
      s->value = cond;
      return s;
    }
    if (!then) failHere("'then' or the end of the line after the if condition");
    Stmt* s = newStmt(StmtKind::IfLine, loc);
    s->value = cond;
    Nested level(*this, loc);
    s->body.push_back(statement(true));
    if (accept(Tok::KwElse)) s->body.push_back(statement(true));
    s->body.shrink_to_fit();
    return s;
  }

  // for -> FOR name '=' expr TO expr [STEP expr]
  Stmt* forStmt(bool inLineIf) {
    SourceLoc loc = cur().loc;
    ++pos_;
    noBlockInLineIf(inLineIf, loc, "for");
    Stmt* s = newStmt(StmtKind::For, loc);
    const Token& v = expect(Tok::Ident, "the loop variable after for");
    s->target = varExpr(v);
    expect(Tok::Assign, "'=' after the loop variable");
    s->exprs.push_back(expression());
    expect(Tok::KwTo, "'to'");
    s->exprs.push_back(expression());
    if (accept(Tok::KwStep)) s->exprs.push_back(expression());
    s->exprs.shrink_to_fit();
    return s;
  }

  // sub -> SUB name ['(' [['&'] name {',' ['&'] name}] ')']
  Stmt* subStmt(bool inLineIf) {
    SourceLoc loc = cur().loc;
    ++pos_;
    noBlockInLineIf(inLineIf, loc, "sub");
    Stmt* s = newStmt(StmtKind::Sub, loc);
    const Token& name = expect(Tok::Ident, "a sub name");
    s->name = name.text;
    s->nameLoc = name.loc;
    if (accept(Tok::LParen)) {
      if (!at(Tok::RParen)) {
        do {
          ast::Param p;
          p.byRef = accept(Tok::Amp);
          const Token& pn = expect(Tok::Ident, "a parameter name");
          p.name = pn.text;
          p.loc = pn.loc;
          s->params.push_back(p);
        } while (accept(Tok::Comma));
      }
      expect(Tok::RParen, "')' to close the parameter list");
    }
    return s;
  }

  // dim -> DIM name ['[' expr {',' expr} ']'] {',' name [...]}
  Stmt* dimStmt() {
    Stmt* s = newStmt(StmtKind::Dim, cur().loc);
    ++pos_;
    do {
      const Token& name = expect(Tok::Ident, "an array name after dim");
      Expr* e = varExpr(name);
      if (accept(Tok::LBracket)) {
        e->kind = ExprKind::Index;
        argList(e->args);
        expect(Tok::RBracket, "']' to close the array size");
      } else if (accept(Tok::LParen)) {
        e->kind = ExprKind::Index;
        argList(e->args);
        expect(Tok::RParen, "')' to close the array size");
      }
      s->exprs.push_back(e);
    } while (accept(Tok::Comma));
    return s;
  }

  // data -> DATA name (';' | ',') expr {',' expr}
  Stmt* dataStmt() {
    Stmt* s = newStmt(StmtKind::Data, cur().loc);
    ++pos_;
    const Token& name = expect(Tok::Ident, "an array name after data");
    s->name = name.text;
    s->nameLoc = name.loc;
    if (!accept(Tok::Semicolon) && !accept(Tok::Comma)) failHere("';' after the array name");
    argList(s->exprs);
    return s;
  }

  bool isAssignOp(Tok k) const {
    return k == Tok::Assign || k == Tok::PlusAssign || k == Tok::MinusAssign ||
           k == Tok::StarAssign || k == Tok::SlashAssign || k == Tok::PlusPlus ||
           k == Tok::MinusMinus;
  }

  // Statement starting with a name: assignment, built-in command or sub call.
  Stmt* identStmt() {
    const Token& name = cur();
    Tok next = peek().kind;
    if (isAssignOp(next) || next == Tok::LBracket) return assignment();
    if (const Builtin* b = builtins_.find(name.text, BuiltinKind::Command)) return command(*b);
    if (std::optional<std::string> why = builtins_.misuse(name.text, NamePlace::Statement))
      fail(name.loc, std::move(*why), "rb-misplaced-builtin");
    if (next == Tok::LParen) {
      Stmt* s = newStmt(StmtKind::Call, name.loc);
      s->name = name.text;
      s->nameLoc = name.loc;
      s->paren = true;
      pos_ += 2;
      if (!at(Tok::RParen)) argList(s->exprs);
      expect(Tok::RParen, "')' to close the argument list");
      return s;
    }
    std::string msg = "unknown command '" + std::string(name.text) + "'";
    std::string hint = suggestCommand(builtins_, name.text);
    if (!hint.empty()) msg += "; did you mean '" + hint + "'?";
    // A misspelt closer ("nxt" for next) still closes its block (see keepBlockOpener).
    std::optional<StmtKind> closer = closerKind(hint);
    if (closer && !diags_.hasErrorOnLine(name.loc.file, name.loc.line))
      guessedCloser_ = GuessedCloser{*closer, name.loc};
    fail(name.loc, msg, "rb-unknown-command", hint, name.text.size());
  }

  /// The closer a keyword is (`next`, `wend`, `until`, `endif`), if it is one.
  static std::optional<StmtKind> closerKind(std::string_view word) {
    switch (keywordKind(word)) {
      case Tok::KwNext: return StmtKind::Next;
      case Tok::KwWend: return StmtKind::Wend;
      case Tok::KwUntil: return StmtKind::Until;
      case Tok::KwEndIf: return StmtKind::EndIf;
      default: return std::nullopt;
    }
  }

  // assignment -> lvalue ('=' | '+=' | '-=' | '*=' | '/=') expr | lvalue ('++' | '--')
  Stmt* assignment() {
    SourceLoc loc = cur().loc;
    Stmt* s = newStmt(StmtKind::Assign, loc);
    s->target = lvalue();
    if (!isAssignOp(cur().kind)) failHere("'=' in an assignment");
    s->op = advance().kind;
    if (s->op != Tok::PlusPlus && s->op != Tok::MinusMinus) {
      s->value = expression();
      noValuesSideBySide(Place::Value);
    }
    return s;
  }

  // command -> NAME [args] | NAME '(' args ')'
  Stmt* command(const Builtin& b) {
    Stmt* s = newStmt(StmtKind::Command, cur().loc);
    s->name = cur().text;
    s->nameLoc = cur().loc;
    ++pos_;
    if (atLineEnd() || at(Tok::KwElse)) return s;
    if (b.printList) {
      printList(s);
      return s;
    }
    if (at(Tok::LParen) && parenthesizedArgList()) {
      s->paren = true;
      ++pos_;
      argList(s->exprs);
      expect(Tok::RParen, "')'");
      return s;
    }
    argList(s->exprs);
    return s;
  }

  /// True when the tokens from '(' to the matching ')' hold a top-level comma and the line ends
  /// right after the ')': `rLocate(400, 300)` is an argument list, `rForward (a+b)*2` is not.
  bool parenthesizedArgList() const {
    int depth = 0;
    bool comma = false;
    for (size_t i = pos_; i < toks_.size(); ++i) {
      Tok k = toks_[i].kind;
      if (k == Tok::Newline || k == Tok::Eof) return false;
      if (k == Tok::LParen || k == Tok::LBracket) ++depth;
      if (k == Tok::RParen || k == Tok::RBracket) {
        if (--depth == 0) {
          Tok after = i + 1 < toks_.size() ? toks_[i + 1].kind : Tok::Eof;
          return comma && (after == Tok::Newline || after == Tok::Eof || after == Tok::KwElse);
        }
      }
      if (k == Tok::Comma && depth == 1) comma = true;
    }
    return false;
  }

  /// The arguments go to `out` at exactly their number: the items are gathered on a stack
  /// first, so that no list keeps spare room (a program has a list for every call).
  void argList(std::vector<Expr*>& out) {
    size_t base = items_.size();
    do {
      Expr* e = expression();
      items_.push_back(e);
    } while (accept(Tok::Comma));
    out.reserve(out.size() + (items_.size() - base));
    out.insert(out.end(), items_.begin() + static_cast<long>(base), items_.end());
    items_.resize(base);
  }

  Expr* varExpr(const Token& t) {
    Expr* e = arena_.expr();
    e->kind = ExprKind::Var;
    e->loc = t.loc;
    e->text = t.text;
    return e;
  }

  // lvalue -> name | name '[' expr {',' expr} ']'
  Expr* lvalue() {
    const Token& name = expect(Tok::Ident, "a variable name");
    Expr* e = varExpr(name);
    if (accept(Tok::LBracket)) {
      e->kind = ExprKind::Index;
      argList(e->args);
      expect(Tok::RBracket, "']' to close the index");
    }
    return e;
  }

  // expression -> precedence climbing over binaryOpInfo()
  Expr* expression() {
    Expr* e = binary(1);
    if (!e->end.valid() && pos_ > 0) e->end = tokenEnd(toks_[pos_ - 1]);
    return e;
  }

  /// The last character of a token (a string's closing quote).
  static SourceLoc tokenEnd(const Token& t) {
    SourceLoc end = t.loc;
    if (t.kind == Tok::String) end.col += static_cast<uint32_t>(t.text.size() + 1);
    else if (!t.text.empty()) end.col += static_cast<uint32_t>(t.text.size() - 1);
    return end;
  }

  Expr* binary(int minPrec) {
    // Each operator folded here makes the tree one level deeper on the left; the levels are
    // given back however this returns (also when a syntax error unwinds through it).
    struct Chain {
      Parser& p;
      int folded = 0;
      ~Chain() { p.treeDepth_ -= folded; }
    } chain{*this};
    Expr* left = unary();
    for (;;) {
      Tok op = cur().kind;
      BinaryOpInfo info = binaryOpInfo(op);
      if (info.prec == 0 || info.prec < minPrec) return left;
      SourceLoc loc = cur().loc;
      deepen(loc);
      ++chain.folded;
      ++pos_;
      Expr* right = nested(loc, [&] { return binary(info.rightAssoc ? info.prec : info.prec + 1); });
      Expr* e = arena_.expr();
      e->kind = ExprKind::Binary;
      e->op = op;
      e->loc = loc;
      e->args = {left, right};
      left = e;
    }
  }

  // unary -> ('-' | '+' | NOT | '!' | '~') unary | postfix
  Expr* unary() {
    Tok k = cur().kind;
    if (k == Tok::Minus || k == Tok::Plus || k == Tok::KwNot || k == Tok::Bang || k == Tok::Tilde) {
      SourceLoc loc = cur().loc;
      ++pos_;
      Expr* operand = nested(loc, [&] { return unary(); });
      // Fold a minus sign into a number literal so that -5 is a constant.
      if (k == Tok::Minus && operand->kind == ExprKind::Int && operand->ival != INT64_MIN) {
        operand->ival = -operand->ival;
        operand->loc = loc;
        return operand;
      }
      if (k == Tok::Minus && operand->kind == ExprKind::Float) {
        operand->dval = -operand->dval;
        operand->loc = loc;
        return operand;
      }
      if (k == Tok::Plus) return operand;
      Expr* e = arena_.expr();
      e->kind = ExprKind::Unary;
      e->op = k;
      e->loc = loc;
      e->args = {operand};
      return e;
    }
    return primary();
  }

  // primary -> number | string | '(' expression ')' | name | name '(' args ')' | name '[' args ']'
  Expr* primary() {
    const Token& t = cur();
    Expr* e = arena_.expr();
    e->loc = t.loc;
    switch (t.kind) {
      case Tok::Int:
        e->kind = ExprKind::Int;
        e->ival = t.intValue;
        ++pos_;
        return e;
      case Tok::Float:
        e->kind = ExprKind::Float;
        e->dval = t.floatValue;
        ++pos_;
        return e;
      case Tok::String:
        e->kind = ExprKind::Str;
        e->text = t.text;
        ++pos_;
        return e;
      case Tok::LParen: {
        ++pos_;
        Expr* inner = nested(t.loc, [&] { return expression(); });
        expect(Tok::RParen, "')'");
        return inner;
      }
      case Tok::Ident: {
        e->text = t.text;
        ++pos_;
        if (accept(Tok::LParen)) {
          e->kind = ExprKind::Call;
          if (!at(Tok::RParen)) nested(t.loc, [&] { argList(e->args); });
          expect(Tok::RParen, "')' to close the argument list");
          return e;
        }
        if (accept(Tok::LBracket)) {
          e->kind = ExprKind::Index;
          nested(t.loc, [&] { argList(e->args); });
          expect(Tok::RBracket, "']' to close the index");
          return e;
        }
        e->kind = ExprKind::Var;
        return e;
      }
      default: break;
    }
    if (t.kind >= Tok::KwAnd) {
      fail(t.loc, "expected an expression, found the keyword '" + std::string(t.text) + "'");
    }
    failHere("an expression");
  }


  TokenLines& lines_;
  std::vector<Token> toks_;  ///< the line being parsed
  std::vector<Expr*> items_;  ///< argument lists being gathered (see argList)
  /// The closer the unknown command just reported looks like, and where (see keepBlockOpener).
  struct GuessedCloser {
    StmtKind kind;
    SourceLoc loc;
  };
  std::optional<GuessedCloser> guessedCloser_;
  ast::Arena& arena_;
  const BuiltinTable& builtins_;
  DiagnosticList& diags_;
  size_t pos_ = 0;
  int depth_ = 0;
  int treeDepth_ = 0;
};

}  // namespace

std::vector<ast::Stmt*> parseTokens(const std::vector<Token>& tokens, ast::Arena& arena,
                                    const BuiltinTable& builtins, DiagnosticList& diags) {
  TokenVectorLines lines(tokens);
  return Parser(lines, arena, builtins, diags).run();
}

std::vector<ast::Stmt*> parseFile(const SourceSet& sources, uint32_t fileIndex, ast::Arena& arena,
                                  const BuiltinTable& builtins, DiagnosticList& diags) {
  LexedLines lines(sources, fileIndex, diags);
  return Parser(lines, arena, builtins, diags).run();
}

ast::Expr* parseExpression(const SourceSet& sources, uint32_t fileIndex, ast::Arena& arena,
                           const BuiltinTable& builtins, DiagnosticList& diags) {
  LexedLines lines(sources, fileIndex, diags);
  return Parser(lines, arena, builtins, diags).expressionLine();
}

void parseFileLines(const SourceSet& sources, uint32_t fileIndex, ast::Arena& arena,
                    const BuiltinTable& builtins, DiagnosticList& diags,
                    const std::function<void(const std::vector<ast::Stmt*>&)>& onLine) {
  LexedLines lines(sources, fileIndex, diags);
  Parser(lines, arena, builtins, diags).run(onLine);
}

}  // namespace rb
