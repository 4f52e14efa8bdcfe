#include "lang/compiler.h"

#include <cstring>
#include <map>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "lang/ast_walk.h"
#include "lang/builtins.h"
#include "lang/suggest.h"

namespace rb {

using ast::Expr;
using ast::ExprKind;
using ast::Stmt;
using ast::StmtKind;

namespace {

struct CompileError {};

/// A jump target: an address, and how many statements the code falling into it has counted
/// but not yet reported. A jump arriving there subtracts that many, so that the next transfer
/// (which reports them) counts only statements that really ran on each path.
struct Target {
  uint32_t pc = 0;
  int32_t pending = 0;
};

/// Statement counts above this are flushed with a Steps instruction, keeping every count in the
/// 16-bit field of an instruction.
constexpr uint32_t kMaxPending = 8000;

std::string lineOf(SourceLoc loc) { return "line " + std::to_string(loc.line); }

/// What a block statement left open, waiting for its closer.
struct Block {
  enum Kind { If, For, While, Repeat };
  Block(Kind k, const Stmt* s) : kind(k), stmt(s) {}
  Kind kind;
  const Stmt* stmt = nullptr;
  std::vector<uint32_t> nextPatches;      ///< if: jumps to the next elseif/else/endif
  std::vector<uint32_t> endPatches;       ///< if: jumps to endif
  std::vector<uint32_t> breakPatches;     ///< loops: jumps to the loop exit
  std::vector<uint32_t> continuePatches;  ///< loops: jumps to the loop test
  bool sawElse = false;
  Target bodyStart;                       ///< loops: first body instruction
  uint32_t entryJump = 0;                 ///< while: the jump to the test
  uint32_t forVar = 0, forLimit = 0;      ///< for: operands
};

struct Scope {
  int sub = -1;  ///< index in Program::subs, -1 for code outside subs
  std::unordered_map<std::string_view, uint32_t> locals;  ///< sub scope: frame index
  uint32_t localCount = 0;
  uint32_t nextTemp = 0;
  uint32_t maxTemp = 0;
  std::vector<uint32_t> gosubs;  ///< Gosub instructions whose frame bump is patched at the end
  std::unordered_map<const Stmt*, uint32_t> forSlots;  ///< hidden limit/step slots of for loops
};

class Compiler {
 public:
  Compiler(const LoadedProgram& lp, const CompileOptions& options, DiagnosticList& diags,
           Program& out)
      : lp_(lp), builtins_(lp.builtins), options_(options), diags_(diags), p_(out) {}

  void run() {
    p_.builtins = &builtins_;
    p_.lineTracing = options_.lineTracing;
    declare();
    scope_ = &global_;
    const auto& stmts = lp_.stmts;
    for (size_t i = 0; i < stmts.size(); ++i) {
      const Stmt* s = stmts[i];
      // A sub ends at endsub, at the next sub, or at the end of the file it is written in.
      if (inSub() && s->loc.file != subStmt_->loc.file) endSub(SourceLoc{});
      if (s->kind == StmtKind::Sub) {
        if (inSub()) endSub(s->loc);
        beginSub(*s, i);
        continue;
      }
      if (s->kind == StmtKind::EndSub) {
        if (!inSub()) {
          diags_.error(s->loc, "endsub without a sub");
          continue;
        }
        endSub(s->loc);
        continue;
      }
      statement(*s, true);
    }
    if (inSub()) endSub(SourceLoc{});
    closeBlocksAtEnd(SourceLoc{});
    placeTarget();
    emitTransfer(Op::End, 0, 0, 0, lastLoc());
    finishScope(global_);
    p_.mainFrameSize = global_.maxTemp;
    resolveLabels();
    p_.globalCount = static_cast<uint32_t>(p_.globalNames.size());
  }

 private:
  // ---------------------------------------------------------------- declarations (pass 1)

  struct LabelInfo {
    SourceLoc loc;
    Target target;
    bool placed = false;
  };

  /// Finds labels and subs before compiling, so that forward references resolve.
  void declare() {
    arrays_ = ast::arrayNames(lp_.stmts);
    for (const Stmt* s : lp_.stmts) {
      if (s->kind == StmtKind::Label) {
        auto [it, fresh] = labels_.try_emplace(s->name, LabelInfo{s->loc, Target{}, false});
        if (!fresh) {
          diags_.error(s->loc, "duplicate label '" + std::string(s->name) + "'");
          diags_.note(it->second.loc, "'" + std::string(s->name) + "' was first defined here");
        }
      } else if (s->kind == StmtKind::Sub && !s->broken) {
        if (subIndex_.count(s->name)) {
          diags_.error(s->nameLoc, "duplicate sub '" + std::string(s->name) + "'");
          diags_.note(p_.subs[subIndex_[s->name]].loc,
                      "'" + std::string(s->name) + "' was first defined here");
          continue;
        }
        if (std::optional<std::string> why = builtins_.misuse(s->name, NamePlace::Sub))
          diags_.error(s->nameLoc, std::move(*why));
        SubInfo info;
        info.name = std::string(s->name);
        info.loc = s->nameLoc;
        info.paramCount = static_cast<uint32_t>(s->params.size());
        std::unordered_set<std::string_view> seen;
        for (const ast::Param& prm : s->params) {
          if (!seen.insert(prm.name).second)
            diags_.error(prm.loc, "parameter '" + std::string(prm.name) + "' appears twice");
          info.byRef.push_back(prm.byRef);
        }
        subIndex_[s->name] = static_cast<uint32_t>(p_.subs.size());
        p_.subs.push_back(std::move(info));
      }
    }
    for (const auto& [name, info] : labels_) {
      if (subIndex_.count(name)) {
        diags_.error(info.loc, "label '" + std::string(name) + "' has the name of a sub");
      }
    }
  }

  bool isByRef(std::string_view sub, size_t i) const {
    auto it = subIndex_.find(sub);
    if (it == subIndex_.end()) return false;
    const SubInfo& info = p_.subs[it->second];
    return i < info.byRef.size() && info.byRef[i];
  }

  // ---------------------------------------------------------------- subs and scopes

  bool inSub() const { return scope_ != &global_; }

  void beginSub(const Stmt& s, size_t index) {
    closeBlocksAtEnd(s.loc);  // blocks cannot continue into a sub
    auto it = subIndex_.find(s.name);
    int sub = it == subIndex_.end() ? -1 : static_cast<int>(it->second);
    placeTarget();
    subSkip_ = emitTransfer(Op::Jump, 0, 0, 0, s.loc);  // code falling into a sub skips its body
    subScope_ = Scope{};
    subScope_.sub = sub;
    scope_ = &subScope_;
    subStmt_ = &s;
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
    for (size_t i = index + 1; i < lp_.stmts.size(); ++i) {
      const Stmt* b = lp_.stmts[i];
      if (b->kind == StmtKind::Sub || b->kind == StmtKind::EndSub || b->loc.file != s.loc.file) break;
      ast::forEachName(*b, builtins_, [&](std::string_view name, SourceLoc, ast::NameUse) {
        if (!isGlobalRef(name) && !arrays_.count(name)) addLocal(name);  // arrays are global
      }, byRef);
      if (b->kind == StmtKind::For) {
        subScope_.forSlots[b] = subScope_.localCount;
        subScope_.localCount += 2;
        if (names) {
          names->emplace_back("(for limit)");
          names->emplace_back("(for step)");
        }
      }
    }
    if (sub >= 0) {
      SubInfo& info = p_.subs[static_cast<size_t>(sub)];
      info.entry = static_cast<uint32_t>(p_.code.size());
      info.localCount = subScope_.localCount;
    }
  }

  void endSub(SourceLoc loc) {
    closeBlocksAtEnd(loc);
    placeTarget();
    // Falling off the end of a sub returns from it.
    emitTransfer(Op::Return, 0, 0, 0, loc.valid() ? loc : lastLoc());
    finishScope(subScope_);
    if (subScope_.sub >= 0) {
      SubInfo& info = p_.subs[static_cast<size_t>(subScope_.sub)];
      info.frameSize = subScope_.localCount + subScope_.maxTemp;
    }
    scope_ = &global_;
    patch(subSkip_, placeTarget());
    subStmt_ = nullptr;
  }

  /// Patches the frame bump of every gosub in the scope now that its frame size is known.
  void finishScope(Scope& sc) {
    uint32_t frame = sc.localCount + sc.maxTemp;
    for (uint32_t pc : sc.gosubs) p_.code[pc].b = frame;
  }

  static bool isGlobalRef(std::string_view name) { return name.size() > 1 && name[0] == '_'; }

  /// The slot of a variable as seen from the current scope.
  uint32_t variable(std::string_view name) {
    if (inSub() && !isGlobalRef(name)) {
      auto it = subScope_.locals.find(name);
      if (it != subScope_.locals.end()) return operand(Base::Frame, it->second);
      // Not found by the pre-scan (cannot happen for names in the body); fall back to a global.
    }
    if (isGlobalRef(name)) name.remove_prefix(1);
    return globalSlot(name);
  }

  uint32_t globalSlot(std::string_view name) {
    auto [it, fresh] = globals_.try_emplace(name, static_cast<uint32_t>(p_.globalNames.size()));
    if (fresh) p_.globalNames.emplace_back(name);
    return operand(Base::Global, it->second);
  }

  uint32_t hiddenGlobalPair() {
    uint32_t first = static_cast<uint32_t>(p_.globalNames.size());
    p_.globalNames.emplace_back("(for limit)");
    p_.globalNames.emplace_back("(for step)");
    return operand(Base::Global, first);
  }

  uint32_t temp() {
    uint32_t t = scope_->localCount + scope_->nextTemp++;
    if (scope_->nextTemp > scope_->maxTemp) scope_->maxTemp = scope_->nextTemp;
    return operand(Base::Frame, t);
  }
  /// n consecutive temporaries; returns the first.
  uint32_t temps(uint32_t n) {
    uint32_t first = scope_->localCount + scope_->nextTemp;
    scope_->nextTemp += n;
    if (scope_->nextTemp > scope_->maxTemp) scope_->maxTemp = scope_->nextTemp;
    return operand(Base::Frame, first);
  }

  // ---------------------------------------------------------------- constants

  uint32_t constant(const Value& v) {
    std::string key;
    if (v.isInt()) {
      key = "i" + std::to_string(v.i());
    } else if (v.isNum()) {
      double d = v.d();
      char bits[sizeof d];
      std::memcpy(bits, &d, sizeof d);
      key = "d" + std::string(bits, sizeof bits);
    } else {
      key = "s" + v.str();
    }
    auto [it, fresh] = constIndex_.try_emplace(key, static_cast<uint32_t>(p_.constants.size()));
    if (fresh) p_.constants.push_back(v);
    return operand(Base::Const, it->second);
  }
  uint32_t intConst(int64_t i) { return constant(Value::integer(i)); }

  // ---------------------------------------------------------------- emission

  uint32_t emit(Op op, uint32_t a, uint32_t b, uint32_t c, SourceLoc loc, uint16_t n = 0) {
    Instr in;
    in.op = op;
    in.a = a;
    in.b = b;
    in.c = c;
    in.n = n;
    p_.code.push_back(in);
    p_.locs.push_back(loc);
    return static_cast<uint32_t>(p_.code.size() - 1);
  }

  /// Emits a control transfer carrying the statements counted since the previous one.
  uint32_t emitTransfer(Op op, uint32_t a, uint32_t b, uint32_t c, SourceLoc loc) {
    auto n = static_cast<uint16_t>(static_cast<int16_t>(pending_));
    pending_ = 0;
    return emit(op, a, b, c, loc, n);
  }

  /// The address of the next instruction, as a jump target.
  Target placeTarget() {
    if (pending_ > kMaxPending) flushSteps();
    return {static_cast<uint32_t>(p_.code.size()), static_cast<int32_t>(pending_)};
  }

  void flushSteps() {
    emit(Op::Steps, 0, 0, 0, lastLoc(), static_cast<uint16_t>(pending_));
    pending_ = 0;
  }

  void patch(uint32_t pc, Target t) {
    Instr& in = p_.code[pc];
    if (in.op == Op::ForPrep || in.op == Op::ForLoop) in.c = t.pc;
    else in.a = t.pc;
    in.n = static_cast<uint16_t>(static_cast<int16_t>(static_cast<int16_t>(in.n) - t.pending));
  }
  void patchAll(const std::vector<uint32_t>& pcs, Target t) {
    for (uint32_t pc : pcs) patch(pc, t);
  }

  SourceLoc lastLoc() const { return p_.locs.empty() ? SourceLoc{} : p_.locs.back(); }

  [[noreturn]] void fail(SourceLoc loc, std::string message) {
    diags_.error(loc, std::move(message));
    throw CompileError{};
  }

  /// Fails when `name` is a built-in's and cannot stand at `place` (the rule is
  /// BuiltinTable::misuse).
  void checkName(std::string_view name, SourceLoc loc, NamePlace place) {
    if (std::optional<std::string> why = builtins_.misuse(name, place)) fail(loc, std::move(*why));
  }
  /// A target that receives a value: a variable, or an element of an array.
  void checkTarget(const Expr& target) {
    checkName(target.text, target.loc, target.kind == ExprKind::Index ? NamePlace::Array : NamePlace::Store);
  }

  // ---------------------------------------------------------------- statements

  void statement(const Stmt& s, bool topLevel) {
    if (topLevel) {
      scope_->nextTemp = 0;
      if (s.kind != StmtKind::Label) {
        if (++pending_ > kMaxPending) flushSteps();
        if (options_.lineTracing) emit(Op::Line, 0, 0, 0, s.loc);
      }
    }
    try {
      statementBody(s);
    } catch (const CompileError&) {
      // Reported; go on with the next statement.
    }
  }

  void statementBody(const Stmt& s) {
    if (s.broken) {
      brokenOpener(s);
      return;
    }
    switch (s.kind) {
      case StmtKind::Assign: assign(s); break;
      case StmtKind::Print: print(s); break;
      case StmtKind::Input: input(s); break;
      case StmtKind::If: {
        Block b(Block::If, &s);
        b.nextPatches = branchFalse(s.value);
        blocks_.push_back(std::move(b));
        break;
      }
      case StmtKind::ElseIf: {
        Block& b = openIf(s, "elseif");
        if (b.sawElse) fail(s.loc, "elseif after else (the if is at " + lineOf(b.stmt->loc) + ")");
        b.endPatches.push_back(emitTransfer(Op::Jump, 0, 0, 0, s.loc));
        patchAll(b.nextPatches, placeTarget());
        b.nextPatches = branchFalse(s.value);
        break;
      }
      case StmtKind::Else: {
        Block& b = openIf(s, "else");
        if (b.sawElse) fail(s.loc, "second else for the if at " + lineOf(b.stmt->loc));
        b.sawElse = true;
        b.endPatches.push_back(emitTransfer(Op::Jump, 0, 0, 0, s.loc));
        patchAll(b.nextPatches, placeTarget());
        b.nextPatches.clear();
        break;
      }
      case StmtKind::EndIf: {
        openIf(s, "endif");
        Block b = std::move(blocks_.back());
        blocks_.pop_back();
        Target end = placeTarget();
        patchAll(b.nextPatches, end);
        patchAll(b.endPatches, end);
        break;
      }
      case StmtKind::IfLine: {
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
        break;
      }
      case StmtKind::For: forStmt(s); break;
      case StmtKind::Next: nextStmt(s); break;
      case StmtKind::While: {
        Block b(Block::While, &s);
        b.entryJump = emitTransfer(Op::Jump, 0, 0, 0, s.loc);  // the test sits at the bottom
        b.bodyStart = placeTarget();
        blocks_.push_back(std::move(b));
        break;
      }
      case StmtKind::Wend: {
        Block b = closeLoop(s, Block::While, "wend", "while");
        if (b.stmt->broken) break;
        Target test = placeTarget();
        patch(b.entryJump, test);
        patchAll(b.continuePatches, test);
        patchAll(branchTrue(b.stmt->value), b.bodyStart);
        patchAll(b.breakPatches, placeTarget());
        break;
      }
      case StmtKind::Repeat: {
        Block b(Block::Repeat, &s);
        b.bodyStart = placeTarget();
        blocks_.push_back(std::move(b));
        break;
      }
      case StmtKind::Until: {
        Block b = closeLoop(s, Block::Repeat, "until", "repeat");
        patchAll(b.continuePatches, placeTarget());
        std::vector<uint32_t> back = branchFalse(s.value);
        patchAll(back, b.bodyStart);
        patchAll(b.breakPatches, placeTarget());
        break;
      }
      case StmtKind::Break:
      case StmtKind::Continue: {
        Block* loop = innermostLoop();
        const char* word = s.kind == StmtKind::Break ? "break" : "continue";
        if (!loop) fail(s.loc, std::string(word) + " outside a loop");
        uint32_t j = emitTransfer(Op::Jump, 0, 0, 0, s.loc);
        (s.kind == StmtKind::Break ? loop->breakPatches : loop->continuePatches).push_back(j);
        break;
      }
      case StmtKind::Goto:
      case StmtKind::Gosub: {
        if (subIndex_.count(s.name) && !labels_.count(s.name))
          fail(s.nameLoc, "'" + std::string(s.name) + "' is a sub: use call " + std::string(s.name) + "(...)");
        uint32_t pc = s.kind == StmtKind::Goto ? emitTransfer(Op::Jump, 0, 0, 0, s.loc)
                                               : emitTransfer(Op::Gosub, 0, 0, 0, s.loc);
        if (s.kind == StmtKind::Gosub) scope_->gosubs.push_back(pc);
        labelFixups_.push_back({pc, s.name, s.nameLoc});
        break;
      }
      case StmtKind::Return: {
        if (s.value) {
          if (!inSub()) fail(s.loc, "return with a value outside a sub");
          uint32_t r = expr(s.value);
          emitTransfer(Op::Return, 0, r, 1, s.loc);
        } else {
          emitTransfer(Op::Return, 0, 0, 0, s.loc);
        }
        break;
      }
      case StmtKind::End: emitTransfer(Op::End, 0, 0, 0, s.loc); break;
      case StmtKind::Label: {
        Target t = placeTarget();
        auto it = labels_.find(s.name);
        if (it != labels_.end() && !it->second.placed && it->second.loc == s.loc) {
          it->second.target = t;
          it->second.placed = true;
        }
        break;
      }
      case StmtKind::Call: callStmt(s); break;
      case StmtKind::Dim: dim(s); break;
      case StmtKind::Data: {
        checkName(s.name, s.nameLoc, NamePlace::Array);
        uint32_t arr = variable(s.name);
        for (const Expr* e : s.exprs) {
          uint32_t v = expr(e);
          emit(Op::DataAppend, arr, v, 0, e->loc);
        }
        break;
      }
      case StmtKind::Command: command(s); break;
      case StmtKind::Sub:
      case StmtKind::EndSub:
      case StmtKind::Include:
        break;
    }
  }

  /// A block statement with a syntax error: the program will not run, so only the pairing
  /// matters (no second error for the same mistake).
  void brokenOpener(const Stmt& s) {
    switch (s.kind) {
      case StmtKind::If: blocks_.emplace_back(Block::If, &s); break;
      case StmtKind::For: {
        Block b(Block::For, &s);
        blocks_.push_back(std::move(b));
        break;
      }
      case StmtKind::While: blocks_.emplace_back(Block::While, &s); break;
      case StmtKind::Repeat: blocks_.emplace_back(Block::Repeat, &s); break;
      case StmtKind::Until: closeLoop(s, Block::Repeat, "until", "repeat"); break;
      default: break;
    }
  }

  Block& openIf(const Stmt& s, const char* word) {
    if (blocks_.empty() || blocks_.back().kind != Block::If) {
      if (!blocks_.empty())
        fail(s.loc, std::string(word) + " does not match the open " + blockWord(blocks_.back()) +
                        " at " + lineOf(blocks_.back().stmt->loc));
      fail(s.loc, std::string(word) + " without if");
    }
    return blocks_.back();
  }

  static const char* blockWord(const Block& b) {
    switch (b.kind) {
      case Block::If: return "if";
      case Block::For: return "for";
      case Block::While: return "while";
      case Block::Repeat: return "repeat";
    }
    return "block";
  }

  Block* innermostLoop() {
    for (auto it = blocks_.rbegin(); it != blocks_.rend(); ++it)
      if (it->kind != Block::If) return &*it;
    return nullptr;
  }

  /// Pops the loop `kind` that `closer` ends. An if still open inside it is an error: the if's
  /// jumps would land after the loop.
  Block closeLoop(const Stmt& s, Block::Kind kind, const char* closer, const char* opener) {
    if (blocks_.empty()) fail(s.loc, std::string(closer) + " without " + opener);
    Block& top = blocks_.back();
    if (top.kind != kind) {
      bool hasOpener = false;
      for (const Block& b : blocks_) hasOpener = hasOpener || b.kind == kind;
      if (!hasOpener) fail(s.loc, std::string(closer) + " without " + opener);
      std::string missing = top.kind == Block::If ? "endif" : top.kind == Block::For ? "next"
                            : top.kind == Block::While ? "wend" : "until";
      fail(s.loc, std::string(closer) + " closes a " + opener + ", but the " + blockWord(top) +
                      " at " + lineOf(top.stmt->loc) + " is still open (missing " + missing + ")");
    }
    Block b = std::move(top);
    blocks_.pop_back();
    return b;
  }

  /// At the end of the file or of a sub: an unclosed if runs to that point (a warning, since
  /// RobotBASIC runs such programs); an unclosed loop is an error.
  void closeBlocksAtEnd(SourceLoc where) {
    Target end = placeTarget();
    for (auto it = blocks_.rbegin(); it != blocks_.rend(); ++it) {
      const Block& b = *it;
      if (b.stmt->broken) continue;  // its line already has an error
      const char* place = where.valid() ? "before the next sub" : "before the end of the file";
      if (b.kind == Block::If) {
        diags_.warning(b.stmt->loc, std::string("if without endif ") + place +
                                        "; the block runs to that point");
        patchAll(b.nextPatches, end);
        patchAll(b.endPatches, end);
      } else {
        std::string missing = b.kind == Block::For ? "next" : b.kind == Block::While ? "wend" : "until";
        diags_.error(b.stmt->loc, std::string(blockWord(b)) + " without " + missing + " " + place);
      }
    }
    blocks_.clear();
  }

  void forStmt(const Stmt& s) {
    // Reported, but the loop still pairs with its next.
    if (std::optional<std::string> why = builtins_.misuse(s.target->text, NamePlace::Store))
      diags_.error(s.target->loc, std::move(*why));
    uint32_t var = variable(s.target->text);
    uint32_t limit;
    if (inSub()) {
      auto it = subScope_.forSlots.find(&s);
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

  void nextStmt(const Stmt& s) {
    Block b = closeLoop(s, Block::For, "next", "for");
    if (b.stmt->broken) return;
    if (!s.name.empty() && s.name != b.stmt->target->text) {
      blocks_.push_back(std::move(b));  // keep the loop open so later statements make sense
      fail(s.nameLoc, "next " + std::string(s.name) + " does not match the for " +
                          std::string(b.stmt->target->text) + " at " + lineOf(b.stmt->loc));
    }
    patchAll(b.continuePatches, placeTarget());
    patch(emitTransfer(Op::ForLoop, b.forVar, b.forLimit, 0, s.loc), b.bodyStart);
    patchAll(b.breakPatches, placeTarget());
  }

  void assign(const Stmt& s) {
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
    uint32_t arr = variable(t->text);
    auto [idx, n] = indices(*t);
    if (s.op == Tok::Assign) {
      uint32_t v = expr(s.value);
      emit(Op::IndexSet, arr, v, idx, s.loc, n);
      return;
    }
    uint32_t cur = temp();
    emit(Op::IndexGet, cur, arr, idx, t->loc, n);
    if (s.op == Tok::PlusPlus || s.op == Tok::MinusMinus) {
      emit(s.op == Tok::PlusPlus ? Op::Add : Op::Sub, cur, cur, intConst(1), s.loc);
    } else {
      uint32_t r = expr(s.value);
      emit(compoundOp(s.op), cur, cur, r, s.loc);
    }
    emit(Op::IndexSet, arr, cur, idx, s.loc, n);
  }

  static Op compoundOp(Tok t) {
    switch (t) {
      case Tok::PlusAssign: return Op::Add;
      case Tok::MinusAssign: return Op::Sub;
      case Tok::StarAssign: return Op::Mul;
      default: return Op::Div;
    }
  }

  /// Index operands of an Index expression: a single index is used in place; several go to
  /// consecutive temporaries.
  std::pair<uint32_t, uint16_t> indices(const Expr& e) {
    if (e.args.size() > 64) fail(e.loc, "too many indices");
    if (e.args.size() == 1) return {expr(e.args[0]), 1};
    uint32_t first = temps(static_cast<uint32_t>(e.args.size()));
    for (size_t i = 0; i < e.args.size(); ++i) exprInto(e.args[i], first + static_cast<uint32_t>(i));
    return {first, static_cast<uint16_t>(e.args.size())};
  }

  uint32_t separators(const std::vector<Tok>& seps) {
    p_.separatorLists.push_back(seps);
    return static_cast<uint32_t>(p_.separatorLists.size() - 1);
  }

  /// Evaluates print-style items into consecutive temporaries.
  uint32_t items(const std::vector<Expr*>& exprs, size_t from) {
    uint32_t n = static_cast<uint32_t>(exprs.size() - from);
    uint32_t first = temps(n);
    for (uint32_t i = 0; i < n; ++i) exprInto(exprs[from + i], first + i);
    return first;
  }

  void print(const Stmt& s) {
    if (s.exprs.size() > 0xffff) fail(s.loc, "too many items");
    uint32_t first = s.exprs.empty() ? 0 : items(s.exprs, 0);
    emit(Op::Print, 0, first, separators(s.seps), s.loc, static_cast<uint16_t>(s.exprs.size()));
  }

  void input(const Stmt& s) {
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
    uint32_t arr = variable(s.target->text);
    auto [idx, n] = indices(*s.target);
    emit(Op::IndexSet, arr, t, idx, s.loc, n);
  }

  void dim(const Stmt& s) {
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

  void checkArity(const Builtin& b, size_t n, SourceLoc loc) {
    if (!b.acceptsCount(static_cast<int>(n))) {
      std::string what = b.kind == BuiltinKind::Command ? "" : "()";
      fail(loc, "'" + std::string(b.name) + what + "' takes " + b.arityText() + " argument" +
                    (b.arityText() == "1" ? "" : "s") + ", got " + std::to_string(n));
    }
  }

  /// Evaluates a built-in's arguments into consecutive temporaries and calls it. Output
  /// parameters are written back to their variables after the call.
  void callBuiltin(const Builtin& b, const std::vector<Expr*>& args, const std::vector<Tok>* seps,
                   uint32_t dest, SourceLoc loc) {
    int n = static_cast<int>(args.size());
    std::vector<const Expr*> outputs(args.size(), nullptr);
    uint32_t first = 0;
    if (b.printList && seps) {
      // Leading fixed parameters, then every remaining item formatted into one string.
      int fixed = b.minArgs - 1;
      if (n < b.minArgs) checkArity(b, args.size(), loc);
      for (int i = 0; i < fixed; ++i)
        if ((*seps)[static_cast<size_t>(i)] != Tok::Comma)
          fail(args[static_cast<size_t>(i)]->loc, "expected ',' after argument " + std::to_string(i + 1));
      first = temps(static_cast<uint32_t>(fixed + 1));
      for (int i = 0; i < fixed; ++i) exprInto(args[static_cast<size_t>(i)], first + static_cast<uint32_t>(i));
      uint32_t itemsFirst = items(args, static_cast<size_t>(fixed));
      std::vector<Tok> rest(seps->begin() + fixed, seps->end());
      emit(Op::Format, first + static_cast<uint32_t>(fixed), itemsFirst, separators(rest), loc,
           static_cast<uint16_t>(n - fixed));
      n = fixed + 1;
    } else {
      checkArity(b, args.size(), loc);
      first = n ? temps(static_cast<uint32_t>(n)) : 0;
      for (int i = 0; i < n; ++i) {
        const Expr* a = args[static_cast<size_t>(i)];
        if (b.param(n, i).out) {
          if (a->kind != ExprKind::Var && a->kind != ExprKind::Index)
            fail(a->loc, "argument " + std::to_string(i + 1) + " of " + std::string(b.name) +
                             " must be a variable: it receives " + std::string(b.param(n, i).name));
          checkTarget(*a);
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
  void store(const Expr& target, uint32_t v) {
    uint32_t var = variable(target.text);
    if (target.kind == ExprKind::Var) {
      emit(Op::Move, var, v, 0, target.loc);
      return;
    }
    auto [idx, n] = indices(target);
    emit(Op::IndexSet, var, v, idx, target.loc, n);
  }

  void command(const Stmt& s) {
    const Builtin* b = builtins_.find(s.name, BuiltinKind::Command);
    if (!b) fail(s.nameLoc, "unknown command '" + std::string(s.name) + "'");
    callBuiltin(*b, s.exprs, b->printList ? &s.seps : nullptr, kNoOperand, s.nameLoc);
  }

  const SubInfo& subNamed(std::string_view name, SourceLoc loc, bool asFunction) {
    auto it = subIndex_.find(name);
    if (it != subIndex_.end()) return p_.subs[it->second];
    std::vector<std::string_view> names;
    for (const SubInfo& si : p_.subs) names.push_back(si.name);
    checkName(name, loc, asFunction ? NamePlace::Call : NamePlace::Sub);
    const auto& builtinNames = builtins_.names(asFunction ? BuiltinKind::Function : BuiltinKind::Command);
    names.insert(names.end(), builtinNames.begin(), builtinNames.end());
    std::string msg = asFunction ? "unknown function '" + std::string(name) + "'"
                                 : "unknown command or sub '" + std::string(name) + "'";
    std::string hint = closestMatch(name, names, true);
    if (!hint.empty()) msg += "; did you mean '" + hint + "'?";
    fail(loc, msg);
  }

  /// Calls a sub: arguments go to consecutive temporaries that become the callee's parameters;
  /// by-reference parameters are copied back to the caller's variables afterwards.
  void callSub(const SubInfo& sub, const std::vector<Expr*>& args, uint32_t dest, SourceLoc loc,
               SourceLoc nameLoc) {
    if (args.size() != sub.paramCount)
      fail(nameLoc, "sub '" + sub.name + "' takes " + std::to_string(sub.paramCount) +
                        " argument" + (sub.paramCount == 1 ? "" : "s") + ", got " +
                        std::to_string(args.size()));
    uint32_t n = static_cast<uint32_t>(args.size());
    uint32_t first = temps(n == 0 ? 1 : n);
    for (uint32_t i = 0; i < n; ++i) {
      const Expr* a = args[i];
      if (sub.byRef[i]) {
        if (a->kind != ExprKind::Var)
          fail(a->loc, "argument " + std::to_string(i + 1) + " of " + sub.name +
                           " is passed by reference (&): it must be a variable");
        checkName(a->text, a->loc, NamePlace::Store);
      }
      if (sub.byRef[i]) {
        // A by-reference argument may be an output: it need not have a value yet.
        emit(Op::Move, first + i, variable(a->text), 0, a->loc);
        p_.code.back().flags = kMoveMayBeUnassigned;
      } else {
        exprInto(a, first + i);
      }
    }
    uint32_t subIdx = static_cast<uint32_t>(&sub - p_.subs.data());
    emitTransfer(Op::CallSub, subIdx, operandIndex(first), dest, loc);
    for (uint32_t i = 0; i < n; ++i)
      if (sub.byRef[i]) emit(Op::Move, variable(args[i]->text), first + i, 0, args[i]->loc);
  }

  void callStmt(const Stmt& s) {
    const SubInfo& sub = subNamed(s.name, s.nameLoc, false);
    callSub(sub, s.exprs, kNoOperand, s.loc, s.nameLoc);
  }

  // ---------------------------------------------------------------- expressions

  /// Compiles `e`, storing the result into `dest`.
  void exprInto(const Expr* e, uint32_t dest) {
    uint32_t r = expr(e, dest);
    if (r != dest) emit(Op::Move, dest, r, 0, e->loc);
  }

  /// Compiles `e` and returns the operand holding its value (a variable, a constant or a
  /// temporary). `dest`, when given, is a good place for the result but may not be used.
  uint32_t expr(const Expr* e, uint32_t dest = kNoOperand) {
    switch (e->kind) {
      case ExprKind::Int: return intConst(e->ival);
      case ExprKind::Float: return constant(Value::number(e->dval));
      case ExprKind::Str: return constant(Value::string(std::string(e->text)));
      case ExprKind::Var: {
        if (const Builtin* c = builtins_.find(e->text, BuiltinKind::Constant)) return intConst(c->constant);
        checkName(e->text, e->loc, NamePlace::Value);
        return variable(e->text);
      }
      case ExprKind::Index: {
        checkName(e->text, e->loc, NamePlace::Array);
        uint32_t arr = variable(e->text);
        auto [idx, n] = indices(*e);
        uint32_t d = dest != kNoOperand ? dest : temp();
        emit(Op::IndexGet, d, arr, idx, e->loc, n);
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
        uint32_t d = dest != kNoOperand ? dest : temp();
        emit(binaryOp(e->op), d, l, r, e->loc);
        return d;
      }
    }
    return 0;
  }

  static bool isLogical(Tok t) {
    return t == Tok::KwAnd || t == Tok::AndAnd || t == Tok::KwOr || t == Tok::OrOr;
  }

  static Op binaryOp(Tok t) {
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

  /// `a and b` / `a or b` as a value (0 or 1), evaluating b only when needed.
  uint32_t logical(const Expr* e, uint32_t dest) {
    uint32_t d = dest != kNoOperand ? dest : temp();
    std::vector<uint32_t> toFalse = branchFalse(e);
    emit(Op::Move, d, intConst(1), 0, e->loc);
    uint32_t skip = emitTransfer(Op::Jump, 0, 0, 0, e->loc);
    patchAll(toFalse, placeTarget());
    emit(Op::Move, d, intConst(0), 0, e->loc);
    patch(skip, placeTarget());
    return d;
  }

  static bool isComparison(Tok t) {
    return t == Tok::Assign || t == Tok::EqEq || t == Tok::NotEq || t == Tok::Less ||
           t == Tok::LessEq || t == Tok::Greater || t == Tok::GreaterEq;
  }

  /// Emits code that falls through when `e` is true and jumps when it is false; returns the
  /// jumps to patch.
  std::vector<uint32_t> branchFalse(const Expr* e) {
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
  std::vector<uint32_t> branchTrue(const Expr* e) {
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

  static Op jumpIfNot(Tok t) {
    switch (t) {
      case Tok::Assign: case Tok::EqEq: return Op::JumpIfNotEq;
      case Tok::NotEq: return Op::JumpIfNotNe;
      case Tok::Less: return Op::JumpIfNotLt;
      case Tok::LessEq: return Op::JumpIfNotLe;
      case Tok::Greater: return Op::JumpIfNotGt;
      default: return Op::JumpIfNotGe;
    }
  }
  static Op jumpIf(Tok t) {
    switch (t) {
      case Tok::Assign: case Tok::EqEq: return Op::JumpIfEq;
      case Tok::NotEq: return Op::JumpIfNe;
      case Tok::Less: return Op::JumpIfLt;
      case Tok::LessEq: return Op::JumpIfLe;
      case Tok::Greater: return Op::JumpIfGt;
      default: return Op::JumpIfGe;
    }
  }

  // ---------------------------------------------------------------- labels

  struct LabelFixup {
    uint32_t pc;
    std::string_view name;
    SourceLoc loc;
  };

  void resolveLabels() {
    std::vector<std::string_view> names;
    for (const auto& [name, info] : labels_) names.push_back(name);
    for (const LabelFixup& f : labelFixups_) {
      auto it = labels_.find(f.name);
      if (it == labels_.end()) {
        std::string msg = "undefined label '" + std::string(f.name) + "'";
        std::string hint = closestMatch(f.name, names, false);
        if (!hint.empty()) msg += "; did you mean '" + hint + "'?";
        diags_.error(f.loc, msg);
        continue;
      }
      patch(f.pc, it->second.target);
    }
  }

  const LoadedProgram& lp_;
  const BuiltinTable& builtins_;
  const CompileOptions& options_;
  DiagnosticList& diags_;
  Program& p_;

  Scope global_;
  Scope subScope_;
  Scope* scope_ = nullptr;
  const Stmt* subStmt_ = nullptr;
  uint32_t subSkip_ = 0;
  uint32_t pending_ = 0;

  std::vector<Block> blocks_;
  std::map<std::string_view, LabelInfo> labels_;
  std::vector<LabelFixup> labelFixups_;
  std::unordered_map<std::string_view, uint32_t> subIndex_;
  std::unordered_map<std::string_view, uint32_t> globals_;
  std::unordered_set<std::string_view> arrays_;  ///< names used as arrays: global in every sub
  std::unordered_map<std::string, uint32_t> constIndex_;
};

}  // namespace

std::unique_ptr<Program> compileProgram(const LoadedProgram& program, const CompileOptions& options,
                                        DiagnosticList& diags) {
  auto out = std::make_unique<Program>();
  Compiler(program, options, diags, *out).run();
  // Errors found while loading (lexer, parser, includes) reject the program too.
  if (diags.hasErrors()) return nullptr;
  return out;
}

}  // namespace rb
