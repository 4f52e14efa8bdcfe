#pragma once
// The compiler's insides, shared by its chapters (not for use outside core/lang/compiler*.cpp):
//
//   compiler.cpp              the driver: declarations (pass 1), the walk over the statement
//                             list, emitting and patching instructions, the constant pool
//   compiler_statements.cpp   one statement: assignment, print, input, dim, data, commands
//   compiler_expressions.cpp  values and conditions: expressions, and/or, branches on a test
//   compiler_blocks.cpp       blocks and labels: if, loops, break/continue, goto/gosub, labels
//   compiler_subs.cpp         subs and scopes: a sub's frame and locals, variables, calls, return
//   compiler_finish.cpp       finishing the code: outputs not copied in, jumps to a return, K forms
//
// Every chapter is a part of one class, Compiler, declared here.

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "lang/abandon.h"
#include "lang/ast_walk.h"
#include "lang/builtins.h"
#include "lang/compiler.h"

namespace rb::compiler {

using ast::Expr;
using ast::ExprKind;
using ast::Stmt;
using ast::StmtKind;

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
/// A jump target is never placed with more pending statements than this, so that a conditional
/// jump's correction for its taken path fits the instruction's 8-bit `flags` (see patch()).
constexpr uint32_t kMaxTargetPending = 255;

/// 'name', for messages (built by appending: GCC 12 warns falsely, -Wrestrict, about some
/// operator+ chains that start with a literal).
inline std::string quoted(std::string_view name) {
  std::string out;
  out.reserve(name.size() + 2);
  out += '\'';
  out += name;
  out += '\'';
  return out;
}

/// "line 12", for messages that point at another statement.
inline std::string lineOf(SourceLoc loc) { return "line " + std::to_string(loc.line); }

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

/// The variables and temporaries of the main program or of one sub.
struct Scope {
  int sub = -1;  ///< index in Program::subs, -1 for code outside subs
  std::unordered_map<std::string_view, uint32_t> locals;  ///< sub scope: frame index
  uint32_t localCount = 0;
  uint32_t nextTemp = 0;
  uint32_t maxTemp = 0;
  std::vector<uint32_t> gosubs;  ///< Gosub instructions whose frame bump is patched at the end
  std::unordered_map<size_t, uint32_t> forSlots;  ///< hidden limit/step slots of for loops, by statement index
};

class Compiler {
 public:
  Compiler(const LoadedProgram& lp, const CompileOptions& options, DiagnosticList& diags,
           Program& out)
      : lp_(lp), builtins_(lp.builtins), options_(options), diags_(diags), p_(out) {}

  /// Compiles the whole program into the Program given at construction.
  void run();

 private:
  struct LabelInfo {
    SourceLoc loc;
    Target target;
    bool placed = false;
  };
  struct LabelFixup {
    uint32_t pc;
    std::string_view name;
    SourceLoc loc;
  };

  // ---- the driver (compiler.cpp)
  void declare();
  void statement(const Stmt& s, bool topLevel);
  void statementBody(const Stmt& s);
  [[noreturn]] void fail(SourceLoc loc, std::string message, const char* code);
  /// Reports `d` (an error) with its notes and abandons the statement.
  [[noreturn]] void fail(Diagnostic d, std::vector<Diagnostic> notes = {});
  void checkName(std::string_view name, SourceLoc loc, NamePlace place);
  std::optional<std::string> misuse(std::string_view name, NamePlace place, bool naming);
  void checkTarget(const Expr& target);
  uint32_t emit(Op op, uint32_t a, uint32_t b, uint32_t c, SourceLoc loc, uint16_t count = 0);
  uint32_t emitTransfer(Op op, uint32_t a, uint32_t b, uint32_t c, SourceLoc loc);
  Target placeTarget();
  void flushSteps();
  void patch(uint32_t pc, Target t);
  void patchAll(const std::vector<uint32_t>& pcs, Target t);
  SourceLoc lastLoc() const { return lastLoc_; }
  /// The address of the next instruction (also when instructions are not kept).
  uint32_t codeSize() const { return codeSize_; }
  uint32_t constant(const Value& v);
  uint32_t intConst(int64_t i) { return constant(Value::integer(i)); }

  // ---- statements (compiler_statements.cpp)
  void assign(const Stmt& s);
  void print(const Stmt& s);
  void input(const Stmt& s);
  void dim(const Stmt& s);
  void data(const Stmt& s);
  void command(const Stmt& s);
  void checkArity(const Builtin& b, const std::vector<Expr*>& args, SourceLoc loc);
  void callBuiltin(const Builtin& b, const std::vector<Expr*>& args, const std::vector<Tok>* seps,
                   uint32_t dest, SourceLoc loc);
  void store(const Expr& target, uint32_t v);
  /// The operands of an element `arr[i, ...]`: the array, and its indices either in
  /// consecutive slots (idx, n of them) or, for two indices into a global array, as two
  /// operands anywhere (idx and idx2, for IndexGet2/IndexSet2).
  struct Element {
    uint32_t arr = 0;
    uint32_t idx = 0;
    uint16_t n = 0;
    uint32_t idx2 = kNoOperand;
  };
  Element element(const Expr& e);
  void emitIndexGet(uint32_t dest, const Element& el, SourceLoc loc);
  void emitIndexSet(const Element& el, uint32_t v, SourceLoc loc);
  std::pair<uint32_t, uint16_t> indices(const Expr& e);
  uint32_t separators(const std::vector<Tok>& seps);
  uint32_t items(const std::vector<Expr*>& exprs, size_t from);

  // ---- expressions (compiler_expressions.cpp)
  void exprInto(const Expr* e, uint32_t dest);
  uint32_t expr(const Expr* e, uint32_t dest = kNoOperand);
  uint32_t logical(const Expr* e, uint32_t dest);
  std::vector<uint32_t> branchFalse(const Expr* e);
  std::vector<uint32_t> branchTrue(const Expr* e);

  // ---- blocks and labels (compiler_blocks.cpp)
  void ifStmt(const Stmt& s);
  void elseIfStmt(const Stmt& s);
  void elseStmt(const Stmt& s);
  void endIfStmt(const Stmt& s);
  void ifLine(const Stmt& s);
  void forStmt(const Stmt& s);
  void nextStmt(const Stmt& s);
  void whileStmt(const Stmt& s);
  void wendStmt(const Stmt& s);
  void repeatStmt(const Stmt& s);
  void untilStmt(const Stmt& s);
  void breakOrContinue(const Stmt& s);
  void gotoOrGosub(const Stmt& s);
  void label(const Stmt& s);
  void brokenOpener(const Stmt& s);
  void guessedCloser(const Stmt& s);
  Block& openIf(const Stmt& s, const char* word);
  Block* innermostLoop();
  Block closeLoop(const Stmt& s, Block::Kind kind, const char* closer, const char* opener);
  void closeBlocksAtEnd(SourceLoc where);
  void resolveLabels();

  // ---- subs and scopes (compiler_subs.cpp)
  bool inSub() const { return scope_ != &global_; }
  bool isByRef(std::string_view sub, size_t i) const;
  void beginSub(const Stmt& sub, const ast::StmtCursor& body, const ast::SubSpan& span);
  void endSub(SourceLoc loc);
  void finishScope(Scope& sc);
  uint32_t variable(std::string_view name);
  uint32_t globalSlot(std::string_view name);
  uint32_t hiddenGlobalPair();
  uint32_t temp();
  uint32_t temps(uint32_t n);
  const SubInfo& subNamed(std::string_view name, SourceLoc loc, bool asFunction);
  void callSub(const SubInfo& sub, const std::vector<Expr*>& args, uint32_t dest, SourceLoc loc,
               SourceLoc nameLoc);
  void callStmt(const Stmt& s);
  void returnStmt(const Stmt& s);

  // ---- finishing the code (compiler_finish.cpp)
  void finishCode();
  uint64_t readBeforeGiven(const SubInfo& sub, uint32_t first, uint32_t count, bool returnReads) const;
  uint32_t outputsFrom(const SubInfo& sub) const;
  void narrowEmptied(SubInfo& sub) const;
  void removeInstructions(const std::vector<bool>& dead);
  void threadJumps();
  void specializeConstants();

  const LoadedProgram& lp_;
  const BuiltinTable& builtins_;
  const CompileOptions& options_;
  DiagnosticList& diags_;
  Program& p_;

  Scope global_;
  Scope subScope_;
  Scope* scope_ = nullptr;
  uint32_t subSkip_ = 0;   ///< the jump that lets code falling into a sub skip its body
  uint32_t pending_ = 0;   ///< statements counted since the last control transfer
  uint32_t codeSize_ = 0;  ///< instructions emitted
  size_t stmtIndex_ = 0;   ///< the index of the statement being compiled
  ast::Arena scratch_;     ///< statements read back from the compact form (LoadOptions::compact)
  ast::Arena scanScratch_; ///< the same, for looking over a sub's body before compiling it
  SourceLoc lastLoc_;      ///< the source position of the last one

  std::vector<Block> blocks_;
  /// Every name the program uses, lower case, once a free name is wanted (misuse).
  std::unique_ptr<std::unordered_set<std::string>> programNames_;
  std::map<std::string_view, LabelInfo> labels_;
  std::vector<LabelFixup> labelFixups_;
  /// A Move that copies a caller's variable into a by-reference parameter before a call.
  struct CopyIn {
    uint32_t pc;
    uint32_t sub;
    uint32_t param;
  };
  std::vector<CopyIn> copyIns_;
  std::unordered_map<std::string_view, uint32_t> subIndex_;
  std::unordered_map<std::string_view, uint32_t> globals_;
  std::unordered_map<int64_t, uint32_t> intConsts_;     ///< the constant pool, by value
  std::unordered_map<uint64_t, uint32_t> floatConsts_;  ///< by the double's bits
  std::unordered_map<std::string, uint32_t> stringConsts_;
};

}  // namespace rb::compiler
