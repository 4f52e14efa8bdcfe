// The compiler's driver: declarations, the walk over the statement list, emitting and patching
// instructions, and the constant pool. The chapters are listed in compiler_internal.h.

#include <algorithm>
#include <cstring>
#include <optional>

#include "lang/compiler_internal.h"
#include "lang/suggest.h"

namespace rb {

namespace compiler {

void Compiler::run() {
  p_.builtins = &builtins_;
  p_.lineTracing = options_.lineTracing;
  declare();
  const std::vector<ast::SubSpan>& spans = lp_.subSpans;
  scope_ = &global_;
  auto nextSpan = spans.begin();
  const ast::SubSpan* open = nullptr;  // the sub being compiled
  ast::StmtCursor cursor = lp_.cursor(scratch_);
  while (!cursor.done()) {
    // A statement read back from the compact form lives until the next reset: blocks still
    // open refer to their opening statement.
    if (blocks_.empty()) scratch_.reset();
    size_t i = cursor.index();
    const Stmt* s = cursor.next();
    stmtIndex_ = i;
    if (options_.onStatement) options_.onStatement(*s, i);
    if (open && i == open->end) {
      bool atEndSub = open->how == ast::SubEnd::EndSub;
      endSub(open->how == ast::SubEnd::EndOfFile ? SourceLoc{} : s->loc);
      open = nullptr;
      if (atEndSub) continue;
    }
    if (nextSpan != spans.end() && nextSpan->begin == i) {
      open = &*nextSpan++;
      beginSub(*s, cursor, *open);
      continue;
    }
    if (s->kind == StmtKind::EndSub) {
      diags_.error(s->loc, "endsub without a sub", "rb-unmatched-block");
      continue;
    }
    statement(*s, true);
    if (diags_.capped()) return;  // too many errors: the rest is not checked
  }
  if (open) endSub(SourceLoc{});
  closeBlocksAtEnd(SourceLoc{});
  placeTarget();
  emitTransfer(Op::End, 0, 0, 0, lastLoc());
  finishScope(global_);
  p_.mainFrameSize = global_.maxTemp;
  resolveLabels();
  if (options_.keepCode && options_.finish && !diags_.hasErrors()) finishCode();
  p_.globalCount = static_cast<uint32_t>(p_.globalNames.size());
  size_t slots = std::max({p_.globalNames.size(), p_.constants.size(), size_t(p_.mainFrameSize)});
  for (const SubInfo& s : p_.subs) slots = std::max<size_t>(slots, s.frameSize);
  if (slots >= kMaxSlots)
    diags_.error(lastLoc(), "the program is too large (more than " + std::to_string(kMaxSlots) +
                                " variables, constants or temporaries in one place)",
                 "rb-program-too-large");
  if (codeSize_ >= kMaxInstructions)
    diags_.error(lastLoc(), "the program is too large (more than " + std::to_string(kMaxInstructions) +
                                " instructions)",
                 "rb-program-too-large");
}

/// Pass 1: declares labels and subs before compiling, so that forward references resolve.
void Compiler::declare() {
  for (const Declaration& s : lp_.declarations) {
    if (s.kind == StmtKind::Label) {
      auto [it, fresh] = labels_.try_emplace(s.name, LabelInfo{s.loc, Target{}, false});
      if (!fresh) {
        diags_.error(s.loc, "duplicate label " + quoted(s.name), "rb-duplicate-label");
        diags_.note(it->second.loc, quoted(s.name) + " was first defined here");
      }
    } else if (s.kind == StmtKind::Sub && !s.broken) {
      if (subIndex_.count(s.name)) {
        diags_.error(s.nameLoc, "duplicate sub " + quoted(s.name), "rb-duplicate-sub");
        diags_.note(p_.subs[subIndex_[s.name]].loc, quoted(s.name) + " was first defined here");
        continue;
      }
      if (std::optional<std::string> why = misuse(s.name, NamePlace::Sub, true))
        diags_.error(s.nameLoc, std::move(*why), "rb-misplaced-builtin");
      SubInfo info;
      info.name = std::string(s.name);
      info.loc = s.nameLoc;
      info.paramCount = static_cast<uint32_t>(s.params.size());
      std::unordered_set<std::string_view> seen;
      for (const ast::Param& prm : s.params) {
        if (!seen.insert(prm.name).second)
          diags_.error(prm.loc, "parameter " + quoted(prm.name) + " appears twice", "rb-duplicate-parameter");
        info.byRef.push_back(prm.byRef);
      }
      subIndex_[s.name] = static_cast<uint32_t>(p_.subs.size());
      p_.subs.push_back(std::move(info));
    }
  }
  for (const auto& [name, info] : labels_) {
    if (subIndex_.count(name)) {
      diags_.error(info.loc, "label " + quoted(name) + " has the name of a sub", "rb-label-is-sub");
    }
  }
}

// ---------------------------------------------------------------- one statement

void Compiler::statement(const Stmt& s, bool topLevel) {
  if (topLevel) {
    scope_->nextTemp = 0;
    if (s.kind != StmtKind::Label) {
      if (++pending_ > kMaxPending) flushSteps();
      if (options_.lineTracing) emit(Op::Line, 0, 0, 0, s.loc);
    }
  }
  try {
    statementBody(s);
  } catch (const StatementAbandoned&) {
    // Reported; go on with the next statement.
  }
}

/// Hands a statement to its chapter.
void Compiler::statementBody(const Stmt& s) {
  if (s.broken) {
    brokenOpener(s);
    return;
  }
  switch (s.kind) {
    // statements (compiler_statements.cpp)
    case StmtKind::Assign: assign(s); break;
    case StmtKind::Print: print(s); break;
    case StmtKind::Input: input(s); break;
    case StmtKind::Dim: dim(s); break;
    case StmtKind::Data: data(s); break;
    case StmtKind::Command: command(s); break;
    case StmtKind::End: emitTransfer(Op::End, 0, 0, 0, s.loc); break;
    // blocks and labels (compiler_blocks.cpp)
    case StmtKind::If: ifStmt(s); break;
    case StmtKind::ElseIf: elseIfStmt(s); break;
    case StmtKind::Else: elseStmt(s); break;
    case StmtKind::EndIf: endIfStmt(s); break;
    case StmtKind::IfLine: ifLine(s); break;
    case StmtKind::For: forStmt(s); break;
    case StmtKind::Next: nextStmt(s); break;
    case StmtKind::While: whileStmt(s); break;
    case StmtKind::Wend: wendStmt(s); break;
    case StmtKind::Repeat: repeatStmt(s); break;
    case StmtKind::Until: untilStmt(s); break;
    case StmtKind::Break:
    case StmtKind::Continue: breakOrContinue(s); break;
    case StmtKind::Goto:
    case StmtKind::Gosub: gotoOrGosub(s); break;
    case StmtKind::Label: label(s); break;
    // subs (compiler_subs.cpp); sub and endsub themselves are handled by run()
    case StmtKind::Call: callStmt(s); break;
    case StmtKind::Return: returnStmt(s); break;
    case StmtKind::Sub:
    case StmtKind::EndSub:
    case StmtKind::Include:
      break;
  }
}

void Compiler::fail(SourceLoc loc, std::string message, const char* code) {
  diags_.error(loc, std::move(message), code);
  throw StatementAbandoned{};
}

void Compiler::fail(Diagnostic d, std::vector<Diagnostic> notes) {
  d.severity = Severity::Error;
  diags_.add(std::move(d));
  for (Diagnostic& n : notes) {
    n.severity = Severity::Note;
    diags_.add(std::move(n));
  }
  throw StatementAbandoned{};
}

/// Fails when `name` is a built-in's and cannot stand at `place` (the rule is
/// BuiltinTable::misuse).
void Compiler::checkName(std::string_view name, SourceLoc loc, NamePlace place) {
  bool naming = place == NamePlace::Store || place == NamePlace::Array;
  if (std::optional<std::string> why = misuse(name, place, naming)) fail(loc, std::move(*why), "rb-misplaced-builtin");
}

/// BuiltinTable::misuse; where the program names a variable, an array or a sub of its own
/// (`naming`), the message ends with a name it could use instead, one that is no built-in's
/// and that the program uses nowhere.
std::optional<std::string> Compiler::misuse(std::string_view name, NamePlace place, bool naming) {
  std::optional<std::string> why = builtins_.misuse(name, place);
  if (why && naming) {
    if (!programNames_) {  // once, the first time
      programNames_ = std::make_unique<std::unordered_set<std::string>>();
      ast::Arena arena;
      for (ast::StmtCursor c = lp_.cursor(arena); !c.done();) {
        arena.reset();
        addNamesOf(*c.next(), *programNames_);
      }
    }
    *why += "; use another name, such as '" + freeName(name, builtins_, *programNames_) + "'";
  }
  return why;
}

/// A target that receives a value: a variable, or an element of an array.
void Compiler::checkTarget(const Expr& target) {
  checkName(target.text, target.loc, target.kind == ExprKind::Index ? NamePlace::Array : NamePlace::Store);
}

// ---------------------------------------------------------------- emission

uint32_t Compiler::emit(Op op, uint32_t a, uint32_t b, uint32_t c, SourceLoc loc, uint16_t count) {
  lastLoc_ = loc;
  if (!options_.keepCode) return codeSize_++;
  Instr in;
  in.op = op;
  in.a = a;
  in.b = b;
  in.c = c;
  in.count = count;
  p_.code.push_back(in);
  p_.locs.push_back(loc);
  return codeSize_++;
}

/// Emits a control transfer carrying the statements counted since the previous one.
uint32_t Compiler::emitTransfer(Op op, uint32_t a, uint32_t b, uint32_t c, SourceLoc loc) {
  uint32_t pc = emit(op, a, b, c, loc);
  if (options_.keepCode) p_.code[pc].steps = static_cast<int16_t>(pending_);
  pending_ = 0;
  return pc;
}

/// The address of the next instruction, as a jump target.
Target Compiler::placeTarget() {
  if (pending_ > kMaxTargetPending) flushSteps();
  return {codeSize_, static_cast<int32_t>(pending_)};
}

void Compiler::flushSteps() {
  emitTransfer(Op::Steps, 0, 0, 0, lastLoc());
}

void Compiler::patch(uint32_t pc, Target t) {
  if (!options_.keepCode) return;
  Instr& in = p_.code[pc];
  jumpTargetField(in) = t.pc;
  if (isConditionalTransfer(in.op)) {
    // Both paths count `steps`; only the taken one skips the statements the fall-through path
    // counted before the target, so the interpreter takes them back (`flags`) when it jumps.
    in.flags = static_cast<uint8_t>(t.pending);
  } else {
    in.steps = static_cast<int16_t>(in.steps - t.pending);
  }
}

void Compiler::patchAll(const std::vector<uint32_t>& pcs, Target t) {
  for (uint32_t pc : pcs) patch(pc, t);
}

// ---------------------------------------------------------------- constants

/// The constant-pool operand of `v`; equal constants (of one type, floats bit for bit) share
/// one entry.
uint32_t Compiler::constant(const Value& v) {
  auto add = [&](auto& index, auto key) {
    auto [it, fresh] = index.try_emplace(std::move(key), static_cast<uint32_t>(p_.constants.size()));
    if (fresh) p_.constants.push_back(v);
    return operand(Base::Const, it->second);
  };
  if (v.isInt()) return add(intConsts_, v.i());
  if (v.isNum()) {
    double d = v.d();
    uint64_t bits;
    std::memcpy(&bits, &d, sizeof d);
    return add(floatConsts_, bits);
  }
  return add(stringConsts_, v.str());
}

}  // namespace compiler

std::unique_ptr<Program> compileProgram(const LoadedProgram& program, const CompileOptions& options,
                                        DiagnosticList& diags) {
  auto out = std::make_unique<Program>();
  compiler::Compiler(program, options, diags, *out).run();
  // Errors found while loading (lexer, parser, includes) reject the program too.
  if (diags.hasErrors()) return nullptr;
  return out;
}

}  // namespace rb
