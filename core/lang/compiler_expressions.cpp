// The compiler, chapter "expressions": the value of an expression into an operand, `and`/`or`
// as values, and conditions compiled to branches (a comparison in an if or a loop test is one
// compare-and-jump instruction).

#include "lang/compiler_internal.h"

namespace rb::compiler {

namespace {

bool isLogical(Tok t) {
  return t == Tok::KwAnd || t == Tok::AndAnd || t == Tok::KwOr || t == Tok::OrOr;
}

Op binaryOp(Tok t) {
  switch (t) {
    case Tok::Plus: return Op::Add;
    case Tok::Minus: return Op::Sub;
    case Tok::Star: return Op::Mul;
    case Tok::Slash: return Op::Div;
    case Tok::Percent: case Tok::KwMod: return Op::Mod;
    case Tok::Caret: return Op::Pow;
    case Tok::Amp: return Op::BitAnd;
    case Tok::Pipe: return Op::BitOr;
    case Tok::Shl: return Op::Shl;
    case Tok::Shr: return Op::Shr;
    case Tok::Assign: case Tok::EqEq: return Op::Eq;
    case Tok::NotEq: return Op::Ne;
    case Tok::Less: return Op::Lt;
    case Tok::LessEq: return Op::Le;
    case Tok::Greater: return Op::Gt;
    default: return Op::Ge;
  }
}

bool isComparison(Tok t) {
  return t == Tok::Assign || t == Tok::EqEq || t == Tok::NotEq || t == Tok::Less ||
         t == Tok::LessEq || t == Tok::Greater || t == Tok::GreaterEq;
}

Op jumpIfNot(Tok t) {
  switch (t) {
    case Tok::Assign: case Tok::EqEq: return Op::JumpIfNotEq;
    case Tok::NotEq: return Op::JumpIfNotNe;
    case Tok::Less: return Op::JumpIfNotLt;
    case Tok::LessEq: return Op::JumpIfNotLe;
    case Tok::Greater: return Op::JumpIfNotGt;
    default: return Op::JumpIfNotGe;
  }
}

Op jumpIf(Tok t) {
  switch (t) {
    case Tok::Assign: case Tok::EqEq: return Op::JumpIfEq;
    case Tok::NotEq: return Op::JumpIfNe;
    case Tok::Less: return Op::JumpIfLt;
    case Tok::LessEq: return Op::JumpIfLe;
    case Tok::Greater: return Op::JumpIfGt;
    default: return Op::JumpIfGe;
  }
}

}  // namespace

/// Compiles `e`, storing the result into `dest`.
void Compiler::exprInto(const Expr* e, uint32_t dest) {
  uint32_t r = expr(e, dest);
  if (r != dest) emit(Op::Move, dest, r, 0, e->loc);
}

/// Compiles `e` and returns the operand holding its value (a variable, a constant or a
/// temporary). `dest`, when given, is a good place for the result but may not be used.
uint32_t Compiler::expr(const Expr* e, uint32_t dest) {
  switch (e->kind) {
    case ExprKind::Int: return intConst(e->ival);
    case ExprKind::Float: return constant(Value::number(e->dval));
    case ExprKind::Str: return constant(Value::string(std::string(e->text)));
    case ExprKind::Var: {
      if (const Builtin* c = builtins_.find(e->text, BuiltinKind::Constant)) return intConst(c->constant);
      checkName(e->text, e->loc, NamePlace::Value);
      uint32_t v = variable(e->text);
      if (options_.keepCode) p_.variableReads.push_back({e->loc, v});
      return v;
    }
    case ExprKind::Index: {
      checkName(e->text, e->loc, NamePlace::Array);
      Element el = element(*e);
      uint32_t d = dest != kNoOperand ? dest : temp();
      emitIndexGet(d, el, e->loc);
      return d;
    }
    case ExprKind::Call: {
      uint32_t d = dest != kNoOperand ? dest : temp();
      if (const Builtin* b = builtins_.find(e->text, BuiltinKind::Function)) {
        callBuiltin(*b, e->args, nullptr, d, e->loc);
        return d;
      }
      const SubInfo& sub = subNamed(e->text, e->loc, true);
      callSub(sub, e->args, d, e->loc, e->loc);
      return d;
    }
    case ExprKind::Unary: {
      uint32_t r = expr(e->args[0]);
      uint32_t d = dest != kNoOperand ? dest : temp();
      Op op = e->op == Tok::Minus ? Op::Neg : e->op == Tok::Tilde ? Op::BitNot : Op::Not;
      emit(op, d, r, 0, e->loc);
      return d;
    }
    case ExprKind::Binary: {
      if (isLogical(e->op)) return logical(e, dest);
      uint32_t l = expr(e->args[0]);
      uint32_t r = expr(e->args[1]);
      // A temporary on the left is this expression's own: the result goes over it, so that
      // `"step " + n + " of " + total` grows one string in place (concatenate) instead of
      // copying it into a new one at every `+`.
      bool leftIsTemp = operandBase(l) == Base::Frame && operandIndex(l) >= scope_->localCount;
      // A temporary on the right is this expression's own too, and read only here.
      bool rightIsTemp = operandBase(r) == Base::Frame && operandIndex(r) >= scope_->localCount;
      uint32_t d = dest != kNoOperand ? dest : leftIsTemp ? l : temp();
      emit(binaryOp(e->op), d, l, r, e->loc);
      // Into a variable or an argument: the string on the left is taken over, not copied.
      if (binaryOp(e->op) == Op::Add && options_.keepCode) {
        if (leftIsTemp && d != l) p_.code.back().flags |= kAddLeftDies;
        if (rightIsTemp && d != r) p_.code.back().flags |= kAddRightDies;
      }
      return d;
    }
  }
  return 0;
}

/// `a and b` / `a or b` as a value (0 or 1), evaluating b only when needed.
uint32_t Compiler::logical(const Expr* e, uint32_t dest) {
  uint32_t d = dest != kNoOperand ? dest : temp();
  std::vector<uint32_t> toFalse = branchFalse(e);
  emit(Op::Move, d, intConst(1), 0, e->loc);
  uint32_t skip = emitTransfer(Op::Jump, 0, 0, 0, e->loc);
  patchAll(toFalse, placeTarget());
  emit(Op::Move, d, intConst(0), 0, e->loc);
  patch(skip, placeTarget());
  return d;
}

/// Emits code that falls through when `e` is true and jumps when it is false; returns the
/// jumps to patch.
std::vector<uint32_t> Compiler::branchFalse(const Expr* e) {
  if (e->kind == ExprKind::Binary) {
    if (e->op == Tok::KwAnd || e->op == Tok::AndAnd) {
      std::vector<uint32_t> a = branchFalse(e->args[0]);
      std::vector<uint32_t> b = branchFalse(e->args[1]);
      a.insert(a.end(), b.begin(), b.end());
      return a;
    }
    if (e->op == Tok::KwOr || e->op == Tok::OrOr) {
      std::vector<uint32_t> toTrue = branchTrue(e->args[0]);
      std::vector<uint32_t> toFalse = branchFalse(e->args[1]);
      patchAll(toTrue, placeTarget());
      return toFalse;
    }
    if (isComparison(e->op)) {
      uint32_t l = expr(e->args[0]);
      uint32_t r = expr(e->args[1]);
      return {emitTransfer(jumpIfNot(e->op), 0, l, r, e->loc)};
    }
  }
  if (e->kind == ExprKind::Unary && (e->op == Tok::KwNot || e->op == Tok::Bang))
    return branchTrue(e->args[0]);
  uint32_t v = expr(e);
  return {emitTransfer(Op::JumpIfFalse, 0, v, 0, e->loc)};
}

/// Emits code that jumps when `e` is true and falls through when it is false.
std::vector<uint32_t> Compiler::branchTrue(const Expr* e) {
  if (e->kind == ExprKind::Binary) {
    if (e->op == Tok::KwOr || e->op == Tok::OrOr) {
      std::vector<uint32_t> a = branchTrue(e->args[0]);
      std::vector<uint32_t> b = branchTrue(e->args[1]);
      a.insert(a.end(), b.begin(), b.end());
      return a;
    }
    if (e->op == Tok::KwAnd || e->op == Tok::AndAnd) {
      std::vector<uint32_t> toFalse = branchFalse(e->args[0]);
      std::vector<uint32_t> toTrue = branchTrue(e->args[1]);
      patchAll(toFalse, placeTarget());
      return toTrue;
    }
    if (isComparison(e->op)) {
      uint32_t l = expr(e->args[0]);
      uint32_t r = expr(e->args[1]);
      return {emitTransfer(jumpIf(e->op), 0, l, r, e->loc)};
    }
  }
  if (e->kind == ExprKind::Unary && (e->op == Tok::KwNot || e->op == Tok::Bang))
    return branchFalse(e->args[0]);
  uint32_t v = expr(e);
  return {emitTransfer(Op::JumpIfTrue, 0, v, 0, e->loc)};
}

}  // namespace rb::compiler
