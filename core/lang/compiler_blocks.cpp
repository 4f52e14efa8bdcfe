// The compiler, chapter "blocks and labels": if/elseif/else/endif, the single-line if, the
// loops (for/next, while/wend, repeat/until) with break and continue, goto/gosub and labels.
// Blocks pair at compile time into jumps; nothing of them is left at run time, so goto and
// gosub may enter and leave blocks freely, as RobotBASIC allows.

#include "lang/compiler_internal.h"
#include "lang/suggest.h"

namespace rb::compiler {

namespace {

const char* blockWord(const Block& b) {
  switch (b.kind) {
    case Block::If: return "if";
    case Block::For: return "for";
    case Block::While: return "while";
    case Block::Repeat: return "repeat";
  }
  return "block";
}

/// The closer a block is waiting for.
const char* closerWord(const Block& b) {
  switch (b.kind) {
    case Block::If: return "endif";
    case Block::For: return "next";
    case Block::While: return "wend";
    case Block::Repeat: return "until";
  }
  return "end";
}

}  // namespace

// ---------------------------------------------------------------- if

void Compiler::ifStmt(const Stmt& s) {
  Block b(Block::If, &s);
  b.nextPatches = branchFalse(s.value);
  blocks_.push_back(std::move(b));
}

void Compiler::elseIfStmt(const Stmt& s) {
  Block& b = openIf(s, "elseif");
  if (b.sawElse) fail(s.loc, "elseif after else (the if is at " + lineOf(b.stmt->loc) + ")", "rb-unmatched-block");
  b.endPatches.push_back(emitTransfer(Op::Jump, 0, 0, 0, s.loc));
  patchAll(b.nextPatches, placeTarget());
  b.nextPatches = branchFalse(s.value);
}

void Compiler::elseStmt(const Stmt& s) {
  Block& b = openIf(s, "else");
  if (b.sawElse) fail(s.loc, "second else for the if at " + lineOf(b.stmt->loc), "rb-unmatched-block");
  b.sawElse = true;
  b.endPatches.push_back(emitTransfer(Op::Jump, 0, 0, 0, s.loc));
  patchAll(b.nextPatches, placeTarget());
  b.nextPatches.clear();
}

void Compiler::endIfStmt(const Stmt& s) {
  openIf(s, "endif");
  Block b = std::move(blocks_.back());
  blocks_.pop_back();
  Target end = placeTarget();
  patchAll(b.nextPatches, end);
  patchAll(b.endPatches, end);
}

/// `if cond then statement [else statement]`, all on one line.
void Compiler::ifLine(const Stmt& s) {
  std::vector<uint32_t> toElse = branchFalse(s.value);
  statement(*s.body[0], false);
  if (s.body.size() > 1) {
    uint32_t skip = emitTransfer(Op::Jump, 0, 0, 0, s.loc);
    patchAll(toElse, placeTarget());
    statement(*s.body[1], false);
    patch(skip, placeTarget());
  } else {
    patchAll(toElse, placeTarget());
  }
}

Block& Compiler::openIf(const Stmt& s, const char* word) {
  if (blocks_.empty() || blocks_.back().kind != Block::If) {
    if (!blocks_.empty())
      fail(s.loc, std::string(word) + " does not match the open " + blockWord(blocks_.back()) +
                      " at " + lineOf(blocks_.back().stmt->loc),
           "rb-unmatched-block");
    fail(s.loc, std::string(word) + " without if", "rb-unmatched-block");
  }
  return blocks_.back();
}

// ---------------------------------------------------------------- loops

void Compiler::forStmt(const Stmt& s) {
  // Reported, but the loop still pairs with its next.
  if (std::optional<std::string> why = misuse(s.target->text, NamePlace::Store, true))
    diags_.error(s.target->loc, std::move(*why), "rb-misplaced-builtin");
  uint32_t var = variable(s.target->text);
  uint32_t limit;
  if (inSub()) {
    auto it = subScope_.forSlots.find(stmtIndex_);
    limit = operand(Base::Frame, it->second);
  } else {
    limit = hiddenGlobalPair();
  }
  exprInto(s.exprs[1], limit);
  if (s.exprs.size() > 2) exprInto(s.exprs[2], limit + 1);
  else emit(Op::Move, limit + 1, intConst(1), 0, s.loc);
  exprInto(s.exprs[0], var);
  Block b(Block::For, &s);
  b.forVar = var;
  b.forLimit = limit;
  b.breakPatches.push_back(emitTransfer(Op::ForPrep, var, limit, 0, s.loc));
  b.bodyStart = placeTarget();
  blocks_.push_back(std::move(b));
}

void Compiler::nextStmt(const Stmt& s) {
  Block b = closeLoop(s, Block::For, "next", "for");
  if (b.stmt->broken) return;
  if (!s.name.empty() && s.name != b.stmt->target->text) {
    blocks_.push_back(std::move(b));  // keep the loop open so later statements make sense
    fail(s.nameLoc, "next " + std::string(s.name) + " does not match the for " +
                        std::string(b.stmt->target->text) + " at " + lineOf(b.stmt->loc),
         "rb-unmatched-block");
  }
  patchAll(b.continuePatches, placeTarget());
  // A loop without a step, or with the step 1, counts up by one: ForLoop1 need not read the step.
  const Expr* step = b.stmt->exprs.size() > 2 ? b.stmt->exprs[2] : nullptr;
  Op op = !step || (step->kind == ExprKind::Int && step->ival == 1) ? Op::ForLoop1 : Op::ForLoop;
  patch(emitTransfer(op, b.forVar, b.forLimit, 0, s.loc), b.bodyStart);
  patchAll(b.breakPatches, placeTarget());
}

void Compiler::whileStmt(const Stmt& s) {
  Block b(Block::While, &s);
  b.entryJump = emitTransfer(Op::Jump, 0, 0, 0, s.loc);  // the test sits at the bottom
  b.bodyStart = placeTarget();
  blocks_.push_back(std::move(b));
}

void Compiler::wendStmt(const Stmt& s) {
  Block b = closeLoop(s, Block::While, "wend", "while");
  if (b.stmt->broken) return;
  Target test = placeTarget();
  patch(b.entryJump, test);
  patchAll(b.continuePatches, test);
  patchAll(branchTrue(b.stmt->value), b.bodyStart);
  patchAll(b.breakPatches, placeTarget());
}

void Compiler::repeatStmt(const Stmt& s) {
  Block b(Block::Repeat, &s);
  b.bodyStart = placeTarget();
  blocks_.push_back(std::move(b));
}

void Compiler::untilStmt(const Stmt& s) {
  Block b = closeLoop(s, Block::Repeat, "until", "repeat");
  patchAll(b.continuePatches, placeTarget());
  std::vector<uint32_t> back = branchFalse(s.value);
  patchAll(back, b.bodyStart);
  patchAll(b.breakPatches, placeTarget());
}

void Compiler::breakOrContinue(const Stmt& s) {
  Block* loop = innermostLoop();
  const char* word = s.kind == StmtKind::Break ? "break" : "continue";
  if (!loop) fail(s.loc, std::string(word) + " outside a loop", "rb-outside-loop");
  uint32_t j = emitTransfer(Op::Jump, 0, 0, 0, s.loc);
  (s.kind == StmtKind::Break ? loop->breakPatches : loop->continuePatches).push_back(j);
}

Block* Compiler::innermostLoop() {
  for (auto it = blocks_.rbegin(); it != blocks_.rend(); ++it)
    if (it->kind != Block::If) return &*it;
  return nullptr;
}

/// Pops the loop `kind` that `closer` ends. An if still open inside it is an error: the if's
/// jumps would land after the loop.
Block Compiler::closeLoop(const Stmt& s, Block::Kind kind, const char* closer,
                          const char* opener) {
  if (blocks_.empty()) fail(s.loc, std::string(closer) + " without " + opener, "rb-unmatched-block");
  Block& top = blocks_.back();
  if (top.kind != kind) {
    bool hasOpener = false;
    for (const Block& b : blocks_) hasOpener = hasOpener || b.kind == kind;
    if (!hasOpener) fail(s.loc, std::string(closer) + " without " + opener, "rb-unmatched-block");
    std::string message = std::string(closer) + " closes a " + opener + ", but the " + blockWord(top) +
                          " at " + lineOf(top.stmt->loc) + " is still open (missing " + closerWord(top) + ")";
    // A loop left open inside (a missing next or wend): the closer ends its own loop all the
    // same, and the inner loops are this error's news, not errors again at the end of the file
    // (no cascade). An if left open may still get its endif after the closer: keep it.
    bool innerLoopsOnly = true;
    for (auto it = blocks_.rbegin(); it != blocks_.rend() && it->kind != kind; ++it)
      innerLoopsOnly = innerLoopsOnly && it->kind != Block::If;
    while (innerLoopsOnly && !blocks_.empty()) {
      bool match = blocks_.back().kind == kind;
      blocks_.pop_back();
      if (match) break;
    }
    fail(s.loc, std::move(message), "rb-unmatched-block");
  }
  Block b = std::move(top);
  blocks_.pop_back();
  return b;
}

// ---------------------------------------------------------------- unclosed and broken blocks

/// At the end of the file or of a sub: an unclosed if runs to that point (a warning, since
/// RobotBASIC runs such programs); an unclosed loop is an error.
void Compiler::closeBlocksAtEnd(SourceLoc where) {
  Target end = placeTarget();
  for (auto it = blocks_.rbegin(); it != blocks_.rend(); ++it) {
    const Block& b = *it;
    if (b.stmt->broken) continue;  // its line already has an error
    const char* place = where.valid() ? "before the next sub" : "before the end of the file";
    if (b.kind == Block::If) {
      diags_.warning(b.stmt->loc, std::string("if without endif ") + place +
                                      "; the block runs to that point",
                     "rb-unclosed-if");
      patchAll(b.nextPatches, end);
      patchAll(b.endPatches, end);
    } else {
      diags_.error(b.stmt->loc, std::string(blockWord(b)) + " without " + closerWord(b) + " " + place,
                   "rb-unclosed-block");
    }
  }
  blocks_.clear();
}

/// A block statement with a syntax error: the program will not run, so only the pairing
/// matters (no second error for the same mistake).
void Compiler::brokenOpener(const Stmt& s) {
  if (!s.name.empty() && (s.kind == StmtKind::Next || s.kind == StmtKind::Wend ||
                          s.kind == StmtKind::Until || s.kind == StmtKind::EndIf)) {
    guessedCloser(s);
    return;
  }
  switch (s.kind) {
    case StmtKind::If: blocks_.emplace_back(Block::If, &s); break;
    case StmtKind::For: blocks_.emplace_back(Block::For, &s); break;
    case StmtKind::While: blocks_.emplace_back(Block::While, &s); break;
    case StmtKind::Repeat: blocks_.emplace_back(Block::Repeat, &s); break;
    case StmtKind::Until: closeLoop(s, Block::Repeat, "until", "repeat"); break;
    default: break;
  }
}

/// A misspelt closer (`nxt`, which the parser reported as an unknown command with "did you
/// mean 'next'?"): when the innermost open block waits for that closer, it closes the block
/// and the parser's error says so, "(the for at line 4 has no next)"; the block is not
/// reported again as unclosed at the end of the file. Otherwise it is left alone.
void Compiler::guessedCloser(const Stmt& s) {
  Block::Kind kind = s.kind == StmtKind::Next ? Block::For
                     : s.kind == StmtKind::Wend ? Block::While
                     : s.kind == StmtKind::Until ? Block::Repeat
                                                  : Block::If;
  if (blocks_.empty() || blocks_.back().kind != kind) return;
  const Block& b = blocks_.back();
  if (Diagnostic* d = diags_.firstErrorAt(s.loc); d && d->code == "rb-unknown-command")
    d->message += std::string(" (the ") + blockWord(b) + " at " + lineOf(b.stmt->loc) + " has no " +
                  closerWord(b) + ")";
  blocks_.pop_back();
}

// ---------------------------------------------------------------- labels, goto and gosub

void Compiler::gotoOrGosub(const Stmt& s) {
  if (subIndex_.count(s.name) && !labels_.count(s.name))
    fail(s.nameLoc, quoted(s.name) + " is a sub: use call " + std::string(s.name) + "(...)",
         "rb-sub-as-label");
  uint32_t pc = s.kind == StmtKind::Goto ? emitTransfer(Op::Jump, 0, 0, 0, s.loc)
                                         : emitTransfer(Op::Gosub, 0, 0, 0, s.loc);
  if (s.kind == StmtKind::Gosub) scope_->gosubs.push_back(pc);
  labelFixups_.push_back({pc, s.name, s.nameLoc});
}

void Compiler::label(const Stmt& s) {
  Target t = placeTarget();
  auto it = labels_.find(s.name);
  if (it != labels_.end() && !it->second.placed && it->second.loc == s.loc) {
    it->second.target = t;
    it->second.placed = true;
  }
}

void Compiler::resolveLabels() {
  std::vector<std::string_view> names;
  for (const auto& [name, info] : labels_) {
    names.push_back(name);
    if (info.placed) p_.labels.push_back({std::string(name), info.target.pc});
  }
  for (const LabelFixup& f : labelFixups_) {
    auto it = labels_.find(f.name);
    if (it == labels_.end()) {
      std::string msg = "undefined label " + quoted(f.name);
      std::string hint = closestMatch(f.name, names, false);
      if (!hint.empty()) msg += "; did you mean '" + hint + "'?";
      Diagnostic& d = diags_.error(f.loc, msg, "rb-undefined-label");
      if (!hint.empty())
        d.fixits.push_back({f.loc, {f.loc.file, f.loc.line, f.loc.col + static_cast<uint32_t>(f.name.size())}, hint});
      continue;
    }
    patch(f.pc, it->second.target);
  }
}

}  // namespace rb::compiler
