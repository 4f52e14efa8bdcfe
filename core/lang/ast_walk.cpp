#include "lang/ast_walk.h"

#include "lang/builtins.h"

namespace rb::ast {

namespace {

using Visit = std::function<void(std::string_view, SourceLoc, NameUse)>;
using ByRef = std::function<bool(std::string_view, size_t)>;

/// Walks the names of one statement; built-in names are not variables and are skipped.
class NameWalker {
 public:
  NameWalker(const BuiltinTable& builtins, const Visit& visit, const ByRef& byRef)
      : builtins_(builtins), visit_(visit), byRef_(byRef) {}

  void expr(const Expr* e) const {
    if (!e) return;
    switch (e->kind) {
      case ExprKind::Var:
        name(e->text, e->loc, NameUse::Read);
        break;
      case ExprKind::Index:
        name(e->text, e->loc, NameUse::Read);
        for (const Expr* a : e->args) expr(a);
        break;
      case ExprKind::Call:
        // A sub's by-reference argument is copied back after the call, as in a call statement.
        if (!builtins_.find(e->text, BuiltinKind::Function)) {
          for (size_t i = 0; i < e->args.size(); ++i) {
            if (byRef_(e->text, i)) target(e->args[i], NameUse::ReadWrite);
            else expr(e->args[i]);
          }
          break;
        }
        for (const Expr* a : e->args) expr(a);
        break;
      default:
        for (const Expr* a : e->args) expr(a);
        break;
    }
  }

  /// A target that receives a value: a variable or an array element (nothing of a built-in's
  /// name, which the compiler rejects).
  void target(const Expr* e, NameUse use) const {
    if (!e || builtins_.findAny(e->text)) return;
    if (e->kind == ExprKind::Index) {
      name(e->text, e->loc, use == NameUse::Write ? NameUse::ArrayWrite : NameUse::ReadWrite);
      for (const Expr* a : e->args) expr(a);
    } else if (e->kind == ExprKind::Var) {
      name(e->text, e->loc, use);
    } else {
      expr(e);
    }
  }

  void name(std::string_view text, SourceLoc loc, NameUse use) const {
    if (!builtins_.findAny(text)) visit_(text, loc, use);
  }

 private:
  const BuiltinTable& builtins_;
  const Visit& visit_;
  const ByRef& byRef_;
};

}  // namespace

void forEachName(const Stmt& s, const BuiltinTable& builtins, const Visit& visit,
                 const std::function<bool(std::string_view, size_t)>& isByRefArg) {
  NameWalker walk(builtins, visit, isByRefArg);
  switch (s.kind) {
    case StmtKind::Assign:
      walk.target(s.target, s.op == Tok::Assign ? NameUse::Write : NameUse::ReadWrite);
      walk.expr(s.value);
      break;
    case StmtKind::Input:
      walk.expr(s.value);
      walk.target(s.target, NameUse::Write);
      break;
    case StmtKind::For:
      for (const Expr* e : s.exprs) walk.expr(e);
      walk.target(s.target, NameUse::Write);
      break;
    case StmtKind::Dim:
      for (const Expr* e : s.exprs) {
        walk.name(e->text, e->loc, NameUse::Write);
        for (const Expr* a : e->args) walk.expr(a);
      }
      break;
    case StmtKind::Data:
      visit(s.name, s.nameLoc, NameUse::ArrayWrite);
      for (const Expr* e : s.exprs) walk.expr(e);
      break;
    case StmtKind::Command: {
      const Builtin* b = builtins.find(s.name, BuiltinKind::Command);
      int n = static_cast<int>(s.exprs.size());
      for (int i = 0; i < n; ++i) {
        bool out = b && !b->printList && b->acceptsCount(n) && b->param(n, i).out;
        if (out) walk.target(s.exprs[static_cast<size_t>(i)], NameUse::Write);
        else walk.expr(s.exprs[static_cast<size_t>(i)]);
      }
      break;
    }
    case StmtKind::Call:
      for (size_t i = 0; i < s.exprs.size(); ++i) {
        if (isByRefArg(s.name, i)) walk.target(s.exprs[i], NameUse::ReadWrite);
        else walk.expr(s.exprs[i]);
      }
      break;
    case StmtKind::Sub:
      for (const Param& p : s.params) visit(p.name, p.loc, NameUse::Write);
      break;
    case StmtKind::IfLine:
      walk.expr(s.value);
      for (const Stmt* b : s.body) forEachName(*b, builtins, visit, isByRefArg);
      break;
    default:
      walk.expr(s.value);
      walk.expr(s.target);
      for (const Expr* e : s.exprs) walk.expr(e);
      break;
  }
}

std::vector<SubSpan> subSpans(const std::vector<Stmt*>& stmts) {
  SubSpanFinder finder;
  for (size_t i = 0; i < stmts.size(); ++i) finder.add(*stmts[i], i);
  return finder.finish(stmts.size());
}

// A sub's body ends at the first statement of another file, at the next sub or at an endsub.
void SubSpanFinder::add(const Stmt& s, size_t index) {
  if (open_) {
    if (s.loc.file != file_) {
      spans_.back().end = index;
      open_ = false;
    } else if (s.kind == StmtKind::Sub || s.kind == StmtKind::EndSub) {
      spans_.back().end = index;
      spans_.back().how = s.kind == StmtKind::Sub ? SubEnd::NextSub : SubEnd::EndSub;
      open_ = false;
    }
  }
  if (!open_ && s.kind == StmtKind::Sub) {
    spans_.push_back(SubSpan{index, 0, SubEnd::EndOfFile});
    open_ = true;
    file_ = s.loc.file;
  }
}

std::vector<SubSpan> SubSpanFinder::finish(size_t count) {
  if (open_) spans_.back().end = count;
  open_ = false;
  return std::move(spans_);
}

namespace {
void indexedNames(const Expr* e, std::unordered_set<std::string_view>& out) {
  if (!e) return;
  if (e->kind == ExprKind::Index) out.insert(e->text);
  for (const Expr* a : e->args) indexedNames(a, out);
}

void arrayNamesOf(const Stmt& s, std::unordered_set<std::string_view>& out) {
  if (s.kind == StmtKind::Data) out.insert(s.name);
  indexedNames(s.target, out);
  indexedNames(s.value, out);
  for (const Expr* e : s.exprs) indexedNames(e, out);
  for (const Stmt* b : s.body) arrayNamesOf(*b, out);
}
}  // namespace

std::unordered_set<std::string_view> arrayNames(const std::vector<Stmt*>& stmts) {
  std::unordered_set<std::string_view> out;
  for (const Stmt* s : stmts) arrayNamesOf(*s, out);
  return out;
}

void addArrayNames(const Stmt& s, std::unordered_set<std::string_view>& out) { arrayNamesOf(s, out); }

}  // namespace rb::ast
