// The compiler, chapter "statements": assignment, print, input, dim, data and built-in commands
// (and the argument passing of built-in calls, which expressions share).

#include <tuple>

#include "lang/compiler_internal.h"

namespace rb::compiler {

namespace {

Op compoundOp(Tok t) {
  switch (t) {
    case Tok::PlusAssign: return Op::Add;
    case Tok::MinusAssign: return Op::Sub;
    case Tok::StarAssign: return Op::Mul;
    default: return Op::Div;
  }
}

}  // namespace

void Compiler::assign(const Stmt& s) {
  const Expr* t = s.target;
  checkTarget(*t);
  if (t->kind == ExprKind::Var) {
    uint32_t var = variable(t->text);
    switch (s.op) {
      case Tok::Assign: exprInto(s.value, var); return;
      case Tok::PlusPlus: emit(Op::Inc, var, 0, 0, s.loc); return;
      case Tok::MinusMinus: emit(Op::Dec, var, 0, 0, s.loc); return;
      default: {
        uint32_t r = expr(s.value);
        emit(compoundOp(s.op), var, var, r, s.loc);
        return;
      }
    }
  }
  // Array element.
  Element el = element(*t);
  if (s.op == Tok::Assign) {
    uint32_t v = expr(s.value);
    emitIndexSet(el, v, s.loc);
    return;
  }
  uint32_t cur = temp();
  emitIndexGet(cur, el, t->loc);
  if (s.op == Tok::PlusPlus || s.op == Tok::MinusMinus) {
    emit(s.op == Tok::PlusPlus ? Op::Add : Op::Sub, cur, cur, intConst(1), s.loc);
  } else {
    uint32_t r = expr(s.value);
    emit(compoundOp(s.op), cur, cur, r, s.loc);
  }
  emitIndexSet(el, cur, s.loc);
}

void Compiler::print(const Stmt& s) {
  if (s.exprs.size() > 0xffff) fail(s.loc, "too many items", "rb-too-many-arguments");
  uint32_t first = s.exprs.empty() ? 0 : items(s.exprs, 0);
  emit(Op::Print, 0, first, separators(s.seps), s.loc, static_cast<uint16_t>(s.exprs.size()));
}

void Compiler::input(const Stmt& s) {
  checkTarget(*s.target);
  uint32_t prompt = 0;
  uint32_t hasPrompt = 0;
  if (s.value) {
    prompt = expr(s.value);
    hasPrompt = 1;
  }
  if (s.target->kind == ExprKind::Var) {
    emit(Op::Input, variable(s.target->text), prompt, hasPrompt, s.loc);
    return;
  }
  uint32_t t = temp();
  emit(Op::Input, t, prompt, hasPrompt, s.loc);
  emitIndexSet(element(*s.target), t, s.loc);
}

void Compiler::dim(const Stmt& s) {
  for (const Expr* e : s.exprs) {
    checkName(e->text, e->loc, NamePlace::Array);
    uint32_t var = variable(e->text);
    if (e->kind == ExprKind::Var) {
      emit(Op::Move, var, intConst(0), 0, e->loc);
      continue;
    }
    auto [first, n] = indices(*e);
    if (n == 1) {  // Dim wants its extents in consecutive slots; one extent may be anywhere
      uint32_t t = temp();
      emit(Op::Move, t, first, 0, e->loc);
      first = t;
    }
    emit(Op::Dim, var, 0, first, e->loc, n);
  }
}

void Compiler::data(const Stmt& s) {
  checkName(s.name, s.nameLoc, NamePlace::Array);
  uint32_t arr = variable(s.name);
  for (const Expr* e : s.exprs) {
    uint32_t v = expr(e);
    emit(Op::DataAppend, arr, v, 0, e->loc);
  }
}

void Compiler::command(const Stmt& s) {
  const Builtin* b = builtins_.find(s.name, BuiltinKind::Command);
  if (!b) fail(s.nameLoc, "unknown command " + quoted(s.name), "rb-unknown-command");
  callBuiltin(*b, s.exprs, b->printList ? &s.seps : nullptr, kNoOperand, s.nameLoc);
}

void Compiler::checkArity(const Builtin& b, const std::vector<Expr*>& args, SourceLoc loc) {
  size_t n = args.size();
  if (b.acceptsCount(static_cast<int>(n))) return;
  std::string what(b.name);
  if (b.kind != BuiltinKind::Command) what += "()";
  Diagnostic d;
  d.code = "rb-argument-count";
  d.message = quoted(what) + " takes " + b.arityText() + " argument" +
              (b.arityText() == "1" ? "" : "s") + ", got " + std::to_string(n);
  d.loc = loc;
  // Too many: the first argument too many, to the end of the last; too few: the name.
  if (b.maxArgs >= 0 && n > static_cast<size_t>(b.maxArgs)) {
    d.loc = args[static_cast<size_t>(b.maxArgs)]->loc;
    d.end = args.back()->end;
  }
  fail(std::move(d), {Diagnostic{Severity::Note, SourceLoc{}, "usage: " + b.usage()}});
}

/// Evaluates a built-in's arguments into consecutive temporaries and calls it. Output
/// parameters are written back to their variables after the call.
void Compiler::callBuiltin(const Builtin& b, const std::vector<Expr*>& args,
                           const std::vector<Tok>* seps, uint32_t dest, SourceLoc loc) {
  int n = static_cast<int>(args.size());
  std::vector<const Expr*> outputs;  // by argument, once there is an output parameter
  uint32_t first = 0;
  if (b.printList && seps) {
    // Leading fixed parameters, then every remaining item formatted into one string.
    int fixed = b.minArgs - 1;
    if (n < b.minArgs) checkArity(b, args, loc);
    for (int i = 0; i < fixed; ++i)
      if ((*seps)[static_cast<size_t>(i)] != Tok::Comma)
        fail(args[static_cast<size_t>(i)]->loc, "expected ',' after argument " + std::to_string(i + 1), "rb-syntax");
    first = temps(static_cast<uint32_t>(fixed + 1));
    for (int i = 0; i < fixed; ++i) exprInto(args[static_cast<size_t>(i)], first + static_cast<uint32_t>(i));
    uint32_t itemsFirst = items(args, static_cast<size_t>(fixed));
    std::vector<Tok> rest(seps->begin() + fixed, seps->end());
    emit(Op::Format, first + static_cast<uint32_t>(fixed), itemsFirst, separators(rest), loc,
         static_cast<uint16_t>(n - fixed));
    n = fixed + 1;
  } else {
    checkArity(b, args, loc);
    first = n ? temps(static_cast<uint32_t>(n)) : 0;
    for (int i = 0; i < n; ++i) {
      const Expr* a = args[static_cast<size_t>(i)];
      if (b.param(n, i).out) {
        if (a->kind != ExprKind::Var && a->kind != ExprKind::Index)
          fail(Diagnostic{Severity::Error, a->loc,
                          "argument " + std::to_string(i + 1) + " of " + std::string(b.name) +
                              " must be a variable: it receives " + std::string(b.param(n, i).name),
                          "rb-output-argument", a->end},
               {Diagnostic{Severity::Note, SourceLoc{}, "usage: " + b.usage()}});
        checkTarget(*a);
        if (outputs.empty()) outputs.assign(args.size(), nullptr);
        outputs[static_cast<size_t>(i)] = a;
        emit(Op::Move, first + static_cast<uint32_t>(i), intConst(0), 0, a->loc);
      } else {
        exprInto(a, first + static_cast<uint32_t>(i));
      }
    }
  }
  emit(Op::CallBuiltin, builtins_.indexOf(b), first, dest, loc, static_cast<uint16_t>(n));
  for (size_t i = 0; i < outputs.size(); ++i) {
    if (!outputs[i]) continue;
    store(*outputs[i], first + static_cast<uint32_t>(i));
  }
}

/// Stores operand `v` into the variable or array element `target`.
void Compiler::store(const Expr& target, uint32_t v) {
  if (target.kind == ExprKind::Var) {
    emit(Op::Move, variable(target.text), v, 0, target.loc);
    return;
  }
  emitIndexSet(element(target), v, target.loc);
}

/// The array and index operands of the element `e` names.
Compiler::Element Compiler::element(const Expr& e) {
  Element el;
  el.arr = variable(e.text);
  if (e.args.size() == 2 && operandBase(el.arr) == Base::Global && operandIndex(el.arr) <= 0xffff) {
    // Two indices, each used where it is (no copies into consecutive slots).
    el.idx = expr(e.args[0]);
    el.idx2 = expr(e.args[1]);
    el.n = 2;
    return el;
  }
  std::tie(el.idx, el.n) = indices(e);
  return el;
}

void Compiler::emitIndexGet(uint32_t dest, const Element& el, SourceLoc loc) {
  if (el.idx2 != kNoOperand)
    emit(Op::IndexGet2, dest, el.idx, el.idx2, loc, static_cast<uint16_t>(operandIndex(el.arr)));
  else
    emit(Op::IndexGet, dest, el.arr, el.idx, loc, el.n);
}

void Compiler::emitIndexSet(const Element& el, uint32_t v, SourceLoc loc) {
  if (el.idx2 != kNoOperand)
    emit(Op::IndexSet2, v, el.idx, el.idx2, loc, static_cast<uint16_t>(operandIndex(el.arr)));
  else
    emit(Op::IndexSet, el.arr, v, el.idx, loc, el.n);
}

/// Index operands of an Index expression: a single index is used in place; several go to
/// consecutive temporaries.
std::pair<uint32_t, uint16_t> Compiler::indices(const Expr& e) {
  if (e.args.size() > 64) fail(e.loc, "too many indices", "rb-too-many-indices");
  if (e.args.size() == 1) return {expr(e.args[0]), 1};
  uint32_t first = temps(static_cast<uint32_t>(e.args.size()));
  for (size_t i = 0; i < e.args.size(); ++i) exprInto(e.args[i], first + static_cast<uint32_t>(i));
  return {first, static_cast<uint16_t>(e.args.size())};
}

uint32_t Compiler::separators(const std::vector<Tok>& seps) {
  p_.separatorLists.push_back(seps);
  return static_cast<uint32_t>(p_.separatorLists.size() - 1);
}

/// Evaluates print-style items into consecutive temporaries.
uint32_t Compiler::items(const std::vector<Expr*>& exprs, size_t from) {
  uint32_t n = static_cast<uint32_t>(exprs.size() - from);
  uint32_t first = temps(n);
  for (uint32_t i = 0; i < n; ++i) exprInto(exprs[from + i], first + i);
  return first;
}

}  // namespace rb::compiler
