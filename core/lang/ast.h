#pragma once
// The parsed program: a flat list of statements, one per source line (a single-line `if` holds
// its then/else statements). Block statements (if/elseif/else/endif, for/next, while/wend,
// repeat/until, sub/endsub) stay separate entries; the compiler pairs them, which lets
// goto/gosub jump into and out of blocks as RobotBASIC allows.

#include <algorithm>
#include <memory>
#include <string_view>
#include <vector>

#include "base/source.h"
#include "lang/token.h"

namespace rb::ast {

enum class ExprKind : uint8_t {
  Int,     ///< integer literal (ival)
  Float,   ///< double literal (dval)
  Str,     ///< string literal (text)
  Var,     ///< variable or constant name (text)
  Index,   ///< array element: text[args...]
  Call,    ///< function call: text(args...) — a built-in or a sub
  Unary,   ///< op args[0]
  Binary,  ///< args[0] op args[1]
};

struct Expr {
  ExprKind kind = ExprKind::Int;
  Tok op = Tok::Eof;
  SourceLoc loc;
  SourceLoc end;  ///< the last character of the expression (set for whole expressions: arguments)
  std::string_view text;
  union {
    int64_t ival = 0;  ///< Int
    double dval;       ///< Float
  };
  std::vector<Expr*> args;
};

enum class StmtKind : uint8_t {
  Assign,    ///< target op value; op is Assign, PlusAssign.. or PlusPlus/MinusMinus (no value)
  Print,     ///< exprs with seps
  Input,     ///< [value = prompt], target
  If,        ///< block if: value = condition
  IfLine,    ///< single-line if: value = condition, body[0] = then, body[1] = else (optional)
  ElseIf,    ///< value = condition
  Else,
  EndIf,
  For,       ///< target = control variable, exprs = {from, to[, step]}
  Next,      ///< name = optional variable
  While,     ///< value = condition
  Wend,
  Repeat,
  Until,     ///< value = condition
  Break,
  Continue,
  Goto,      ///< name = label
  Gosub,     ///< name = label
  Return,    ///< value = optional result (subs only)
  End,
  Label,     ///< name
  Sub,       ///< name, params
  EndSub,
  Call,      ///< name, exprs = arguments (call Name(args) or Name(args))
  Dim,       ///< exprs = Index expressions (name[dims]) or Var (scalar)
  Data,      ///< name, exprs = values
  Command,   ///< name = built-in command as written, exprs = arguments; seps for print-style lists
  Include,   ///< name = the file named by #include (resolved by the loader)
};

struct Param {
  std::string_view name;
  SourceLoc loc;
  bool byRef = false;
};

struct Stmt {
  StmtKind kind = StmtKind::End;
  Tok op = Tok::Eof;
  SourceLoc loc;              ///< first token of the statement
  std::string_view name;      ///< label, sub, command or variable name
  SourceLoc nameLoc;
  Expr* target = nullptr;
  Expr* value = nullptr;
  std::vector<Expr*> exprs;
  std::vector<Tok> seps;      ///< print-style separator after each item (Comma, Semicolon, Eof)
  std::vector<Param> params;
  std::vector<Stmt*> body;    ///< IfLine: then, else
  bool paren = false;         ///< Call/Command written with parentheses around the arguments
  bool broken = false;        ///< a block opener whose line had a syntax error (already
                              ///< reported): it only keeps its closer paired; or, with
                              ///< `name` set to the word as written, a closer guessed from
                              ///< a misspelt word (Next, Wend, Until, EndIf: `nxt`)
};

/// Owns every node of a program; pointers stay valid for its lifetime (or until reset()). Nodes
/// come from blocks of a few hundred, so a node costs its size and nothing more (a big program
/// has millions of them).
class Arena {
 public:
  Expr* expr() { return exprs_.next(true); }
  Stmt* stmt() { return stmts_.next(true); }
  /// A node whose every field the caller sets (lists: clears, then fills): a reused node is
  /// handed out as it was left.
  Expr* exprToOverwrite() { return exprs_.next(false); }
  Stmt* stmtToOverwrite() { return stmts_.next(false); }
  /// Forgets every node handed out: the blocks are reused, each node handed out again as if
  /// new (its lists keep their room). For holding one statement at a time.
  void reset() {
    exprs_.reset();
    stmts_.reset();
  }

 private:
  template <typename T>
  class Pool {
   public:
    T* next(bool renewed) {
      if (used_ == kBlock) {
        if (filled_ == blocks_.size()) blocks_.push_back(std::make_unique<T[]>(kBlock));
        reused_ = filled_ < reusable_;
        ++filled_;
        used_ = 0;
      }
      T* node = &blocks_[filled_ - 1][used_++];
      if (reused_ && renewed) renew(*node);
      return node;
    }
    void reset() {
      reusable_ = std::max(reusable_, filled_);
      filled_ = 0;
      used_ = kBlock;
    }

   private:
    static constexpr size_t kBlock = 256;
    std::vector<std::unique_ptr<T[]>> blocks_;
    size_t filled_ = 0;    ///< blocks in use
    size_t reusable_ = 0;  ///< blocks that held nodes before a reset
    size_t used_ = kBlock;  ///< nodes handed out of the last block in use
    bool reused_ = false;  ///< that block held nodes before
  };
  /// A node as default-constructed, its lists emptied but keeping their room.
  static void renew(Expr& e) {
    e.kind = ExprKind::Int;
    e.op = Tok::Eof;
    e.loc = e.end = SourceLoc{};
    e.text = {};
    e.ival = 0;
    e.args.clear();
  }
  static void renew(Stmt& s) {
    s.kind = StmtKind::End;
    s.op = Tok::Eof;
    s.loc = s.nameLoc = SourceLoc{};
    s.name = {};
    s.target = s.value = nullptr;
    s.exprs.clear();
    s.seps.clear();
    s.params.clear();
    s.body.clear();
    s.paren = s.broken = false;
  }
  Pool<Expr> exprs_;
  Pool<Stmt> stmts_;
};

}  // namespace rb::ast
