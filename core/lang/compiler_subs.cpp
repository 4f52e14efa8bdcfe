// The compiler, chapter "subs and scopes": a sub's frame (parameters, then every other name
// its body uses, then hidden for-loop slots, then temporaries), how a name finds its slot,
// calls to subs and return.

#include "lang/compiler_internal.h"
#include "lang/suggest.h"

namespace rb::compiler {

// ---------------------------------------------------------------- a sub's scope

bool Compiler::isByRef(std::string_view sub, size_t i) const {
  auto it = subIndex_.find(sub);
  if (it == subIndex_.end()) return false;
  const SubInfo& info = p_.subs[it->second];
  return i < info.byRef.size() && info.byRef[i];
}

/// Opens the scope of the sub `span` describes; its body follows, up to endSub().
void Compiler::beginSub(const Stmt& s, const ast::StmtCursor& body, const ast::SubSpan& span) {
  closeBlocksAtEnd(s.loc);  // blocks cannot continue into a sub
  auto it = subIndex_.find(s.name);
  int sub = it == subIndex_.end() ? -1 : static_cast<int>(it->second);
  placeTarget();
  subSkip_ = emitTransfer(Op::Jump, 0, 0, 0, s.loc);  // code falling into a sub skips its body
  subScope_ = Scope{};
  subScope_.sub = sub;
  scope_ = &subScope_;
  // Parameters come first, then every other name the body uses, then hidden for-loop slots.
  std::vector<std::string>* names = sub >= 0 ? &p_.subs[static_cast<size_t>(sub)].slotNames : nullptr;
  auto addLocal = [&](std::string_view name) {
    if (subScope_.locals.try_emplace(name, subScope_.localCount).second) {
      ++subScope_.localCount;
      if (names) names->emplace_back(name);
    }
  };
  for (const ast::Param& prm : s.params) addLocal(prm.name);
  auto byRef = [this](std::string_view n, size_t i) { return isByRef(n, i); };
  for (ast::StmtCursor c(body, scanScratch_); c.index() < span.end;) {
    scanScratch_.reset();
    size_t i = c.index();
    const Stmt* b = c.next();
    ast::forEachName(*b, builtins_, [&](std::string_view name, SourceLoc, ast::NameUse) {
      if (!ast::isGlobalRef(name) && !lp_.arrays.count(name)) addLocal(name);  // arrays are global
    }, byRef);
    if (b->kind == StmtKind::For) {
      subScope_.forSlots[i] = subScope_.localCount;
      subScope_.localCount += 2;
      if (names) {
        names->emplace_back("(for limit)");
        names->emplace_back("(for step)");
      }
    }
  }
  if (sub >= 0) {
    SubInfo& info = p_.subs[static_cast<size_t>(sub)];
    info.entry = codeSize_;
    info.localCount = subScope_.localCount;
  }
}

/// Closes the sub's scope: `loc` is the endsub or the next sub, or invalid at the end of the
/// file (for messages about blocks left open).
void Compiler::endSub(SourceLoc loc) {
  closeBlocksAtEnd(loc);
  placeTarget();
  // Falling off the end of a sub returns from it.
  emitTransfer(Op::Return, 0, 0, 0, loc.valid() ? loc : lastLoc());
  finishScope(subScope_);
  if (subScope_.sub >= 0) {
    SubInfo& info = p_.subs[static_cast<size_t>(subScope_.sub)];
    info.frameSize = subScope_.localCount + subScope_.maxTemp;
    info.end = codeSize_;
    info.emptyFrom = info.paramCount;  // narrowed by the finisher (narrowEmptied)
    info.emptyTo = info.localCount;
  }
  scope_ = &global_;
  patch(subSkip_, placeTarget());
}

/// Patches the frame bump of every gosub in the scope now that its frame size is known.
void Compiler::finishScope(Scope& sc) {
  uint32_t frame = sc.localCount + sc.maxTemp;
  if (options_.keepCode)
    for (uint32_t pc : sc.gosubs) p_.code[pc].b = frame;
}

// ---------------------------------------------------------------- slots

/// The slot of a variable as seen from the current scope.
uint32_t Compiler::variable(std::string_view name) {
  if (inSub() && !ast::isGlobalRef(name)) {
    auto it = subScope_.locals.find(name);
    if (it != subScope_.locals.end()) return operand(Base::Frame, it->second);
    // Not found by the pre-scan (cannot happen for names in the body); fall back to a global.
  }
  return globalSlot(ast::globalName(name));
}

uint32_t Compiler::globalSlot(std::string_view name) {
  auto [it, fresh] = globals_.try_emplace(name, static_cast<uint32_t>(p_.globalNames.size()));
  if (fresh) p_.globalNames.emplace_back(name);
  return operand(Base::Global, it->second);
}

uint32_t Compiler::hiddenGlobalPair() {
  uint32_t first = static_cast<uint32_t>(p_.globalNames.size());
  p_.globalNames.emplace_back("(for limit)");
  p_.globalNames.emplace_back("(for step)");
  return operand(Base::Global, first);
}

uint32_t Compiler::temp() {
  uint32_t t = scope_->localCount + scope_->nextTemp++;
  if (scope_->nextTemp > scope_->maxTemp) scope_->maxTemp = scope_->nextTemp;
  return operand(Base::Frame, t);
}

/// n consecutive temporaries; returns the first.
uint32_t Compiler::temps(uint32_t n) {
  uint32_t first = scope_->localCount + scope_->nextTemp;
  scope_->nextTemp += n;
  if (scope_->nextTemp > scope_->maxTemp) scope_->maxTemp = scope_->nextTemp;
  return operand(Base::Frame, first);
}

// ---------------------------------------------------------------- calls and return

const SubInfo& Compiler::subNamed(std::string_view name, SourceLoc loc, bool asFunction) {
  auto it = subIndex_.find(name);
  if (it != subIndex_.end()) return p_.subs[it->second];
  std::vector<std::string_view> names;
  for (const SubInfo& si : p_.subs) names.push_back(si.name);
  checkName(name, loc, asFunction ? NamePlace::Call : NamePlace::Sub);
  const auto& builtinNames = builtins_.names(asFunction ? BuiltinKind::Function : BuiltinKind::Command);
  names.insert(names.end(), builtinNames.begin(), builtinNames.end());
  std::string msg = (asFunction ? "unknown function " : "unknown command or sub ") + quoted(name);
  std::string hint = closestMatch(name, names, true);
  Diagnostic d{Severity::Error, loc, msg, asFunction ? "rb-unknown-function" : "rb-unknown-command"};
  if (!hint.empty()) {
    d.message += "; did you mean '" + hint + "'?";
    d.fixits.push_back({loc, {loc.file, loc.line, loc.col + static_cast<uint32_t>(name.size())}, hint});
  }
  fail(std::move(d));
}

/// Calls a sub: arguments go to consecutive temporaries that become the callee's parameters;
/// by-reference parameters are copied back to the caller's variables afterwards.
void Compiler::callSub(const SubInfo& sub, const std::vector<Expr*>& args, uint32_t dest,
                       SourceLoc loc, SourceLoc nameLoc) {
  if (args.size() != sub.paramCount)
  {
    Diagnostic d{Severity::Error, nameLoc,
                 "sub '" + sub.name + "' takes " + std::to_string(sub.paramCount) + " argument" +
                     (sub.paramCount == 1 ? "" : "s") + ", got " + std::to_string(args.size()),
                 "rb-argument-count"};
    if (args.size() > sub.paramCount) {
      d.loc = args[sub.paramCount]->loc;
      d.end = args.back()->end;
    }
    fail(std::move(d), {Diagnostic{Severity::Note, sub.loc, "'" + sub.name + "' is defined here"}});
  }
  uint32_t n = static_cast<uint32_t>(args.size());
  uint32_t first = temps(n == 0 ? 1 : n);
  const auto subIdx = static_cast<uint32_t>(&sub - p_.subs.data());
  for (uint32_t i = 0; i < n; ++i) {
    const Expr* a = args[i];
    if (sub.byRef[i]) {
      if (a->kind != ExprKind::Var)
        fail(Diagnostic{Severity::Error, a->loc,
                        "argument " + std::to_string(i + 1) + " of " + sub.name +
                            " is passed by reference (&): it must be a variable",
                        "rb-reference-argument", a->end});
      checkName(a->text, a->loc, NamePlace::Store);
    }
    if (sub.byRef[i]) {
      // A by-reference argument may be an output: it need not have a value yet.
      uint32_t pc = emit(Op::Move, first + i, variable(a->text), 0, a->loc);
      if (options_.keepCode) {
        p_.code.back().flags = kMoveMayBeUnassigned;
        copyIns_.push_back({pc, subIdx, i});
      }
    } else {
      exprInto(a, first + i);
    }
  }
  emitTransfer(Op::CallSub, subIdx, operandIndex(first), dest, loc);
  for (uint32_t i = 0; i < n; ++i)
    if (sub.byRef[i]) emit(Op::Move, variable(args[i]->text), first + i, 0, args[i]->loc);
}

void Compiler::callStmt(const Stmt& s) {
  const SubInfo& sub = subNamed(s.name, s.nameLoc, false);
  callSub(sub, s.exprs, kNoOperand, s.loc, s.nameLoc);
}

void Compiler::returnStmt(const Stmt& s) {
  if (s.value) {
    if (!inSub()) fail(s.loc, "return with a value outside a sub", "rb-return-outside-sub");
    uint32_t r = expr(s.value);
    emitTransfer(Op::Return, 0, r, 1, s.loc);
  } else {
    emitTransfer(Op::Return, 0, 0, 0, s.loc);
  }
}

}  // namespace rb::compiler
