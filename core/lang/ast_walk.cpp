#include "lang/ast_walk.h"

#include "lang/builtins.h"

namespace rb::ast {

namespace {

using Visit = std::function<void(std::string_view, SourceLoc, NameUse)>;

void walkExpr(const Expr* e, const Visit& visit) {
  if (!e) return;
  switch (e->kind) {
    case ExprKind::Var:
      if (!findAnyBuiltin(e->text)) visit(e->text, e->loc, NameUse::Read);
      break;
    case ExprKind::Index:
      if (!findAnyBuiltin(e->text)) visit(e->text, e->loc, NameUse::Read);
      for (const Expr* a : e->args) walkExpr(a, visit);
      break;
    default:
      for (const Expr* a : e->args) walkExpr(a, visit);
      break;
  }
}

/// A target that receives a value: a variable or an array element.
void walkTarget(const Expr* e, NameUse use, const Visit& visit) {
  if (!e) return;
  if (findAnyBuiltin(e->text)) return;
  if (e->kind == ExprKind::Index) {
    visit(e->text, e->loc, use == NameUse::Write ? NameUse::ArrayWrite : NameUse::ReadWrite);
    for (const Expr* a : e->args) walkExpr(a, visit);
  } else if (e->kind == ExprKind::Var) {
    visit(e->text, e->loc, use);
  } else {
    walkExpr(e, visit);
  }
}

}  // namespace

void forEachName(const Stmt& s, const Visit& visit,
                 const std::function<bool(std::string_view, size_t)>& isByRefArg) {
  switch (s.kind) {
    case StmtKind::Assign:
      walkTarget(s.target, s.op == Tok::Assign ? NameUse::Write : NameUse::ReadWrite, visit);
      walkExpr(s.value, visit);
      break;
    case StmtKind::Input:
      walkExpr(s.value, visit);
      walkTarget(s.target, NameUse::Write, visit);
      break;
    case StmtKind::For:
      for (const Expr* e : s.exprs) walkExpr(e, visit);
      walkTarget(s.target, NameUse::Write, visit);
      break;
    case StmtKind::Dim:
      for (const Expr* e : s.exprs) {
        if (!findAnyBuiltin(e->text)) visit(e->text, e->loc, NameUse::Write);
        for (const Expr* a : e->args) walkExpr(a, visit);
      }
      break;
    case StmtKind::Data:
      visit(s.name, s.nameLoc, NameUse::ArrayWrite);
      for (const Expr* e : s.exprs) walkExpr(e, visit);
      break;
    case StmtKind::Command: {
      const Builtin* b = findBuiltin(s.name, BuiltinKind::Command);
      int n = static_cast<int>(s.exprs.size());
      for (int i = 0; i < n; ++i) {
        bool out = b && !b->printList && b->acceptsCount(n) && b->param(n, i).out;
        if (out) walkTarget(s.exprs[static_cast<size_t>(i)], NameUse::Write, visit);
        else walkExpr(s.exprs[static_cast<size_t>(i)], visit);
      }
      break;
    }
    case StmtKind::Call:
      for (size_t i = 0; i < s.exprs.size(); ++i) {
        if (isByRefArg(s.name, i)) walkTarget(s.exprs[i], NameUse::ReadWrite, visit);
        else walkExpr(s.exprs[i], visit);
      }
      break;
    case StmtKind::Sub:
      for (const Param& p : s.params) visit(p.name, p.loc, NameUse::Write);
      break;
    case StmtKind::IfLine:
      walkExpr(s.value, visit);
      for (const Stmt* b : s.body) forEachName(*b, visit, isByRefArg);
      break;
    default:
      walkExpr(s.value, visit);
      walkExpr(s.target, visit);
      for (const Expr* e : s.exprs) walkExpr(e, visit);
      break;
  }
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

}  // namespace rb::ast
