#pragma once
// Runs a compiled Program on a Machine. Runtime errors stop the run and come back as a
// Diagnostic at the failing instruction's source position.

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "lang/bytecode.h"
#include "base/diagnostic.h"
#include "machine/machine.h"

namespace rb {

struct RunLimits {
  uint64_t maxSteps = 0;        ///< statements to run at most (0: no limit)
  double timeoutSeconds = 0;    ///< real seconds at most (0: no limit)
  uint64_t maxMemoryBytes = 0;  ///< memory rb may use at most, watched by the host (0: no limit)
  uint32_t maxCallDepth = 100000;  ///< nested gosub/call frames at most
  /// Statements between the interpreter's checkpoints (the step limit, the clock, Host::poll).
  /// A host that must answer quickly whatever the program does (the web page's Stop, with no
  /// thread to interrupt the run) asks for fewer; a checkpoint costs tens of nanoseconds.
  uint32_t checkInterval = 1 << 16;

  /// The limits as every host's options give them (rb run's --max-steps, --timeout and
  /// --max-memory in MiB, the page's fields); 0 is no limit.
  static RunLimits of(uint64_t maxSteps, double timeoutSeconds, uint64_t maxMemoryMiB) {
    RunLimits l;
    l.maxSteps = maxSteps;
    l.timeoutSeconds = timeoutSeconds;
    l.maxMemoryBytes = maxMemoryMiB << 20;
    return l;
  }
};

enum class RunStatus {
  Finished,      ///< reached `end` or the end of the program
  RuntimeError,  ///< a runtime error (diagnostic set)
  StepLimit,     ///< --max-steps reached (diagnostic set)
  Timeout,       ///< --timeout reached (diagnostic set)
  Stopped,       ///< the host asked to stop (the user quit a live view)
};

struct RunResult {
  RunStatus status = RunStatus::Finished;
  std::optional<Diagnostic> error;
  uint64_t steps = 0;  ///< statements executed
};

/// A variable as a debugger shows it (the live view's variables pane).
struct VariableView {
  std::string_view name;
  bool local = false;            ///< a parameter or local of the running sub
  const Value* value = nullptr;  ///< valid until the program runs on
};

class Interpreter {
 public:
  Interpreter(const Program& program, Machine& machine);

  /// Runs the program from its first instruction.
  RunResult run(const RunLimits& limits);

  // ---- a read-only look at a running program, for hooks called during run() (Host::onLine)

  /// The named variables now: the globals in the order the program names them, then the running
  /// sub's parameters and locals. Nothing is copied or changed.
  std::vector<VariableView> variables() const;
  /// Nested gosub and sub-call frames now (0: the main code).
  size_t callDepth() const { return depth_; }
  /// The name of the sub running now ("" in the main code and its gosubs).
  std::string_view runningSub() const {
    return sub_ >= 0 ? std::string_view(prog_.subs[static_cast<size_t>(sub_)].name) : std::string_view();
  }

 private:
  struct Frame {
    const Instr* ret;    ///< the instruction after the call
    uint32_t base;       ///< the caller's frame base
    uint32_t dest;       ///< sub calls: where the result goes (kNoOperand: nowhere)
    int32_t sub;         ///< the sub this frame runs (-1: a gosub)
    int32_t callerSub;   ///< the sub the caller ran (-1: main code)
  };

  /// The interpreter runs its own copy of the program's code (code_) whose operands are
  /// re-encoded: slot i of base s becomes i * 16 + s, the slot's byte offset with the base's
  /// number in its low bits (a slot is 16 bytes, so they are free). Finding a slot is then a
  /// mask, a load of the base and an add (runOperand makes one; kNoOperand stays itself).
  static constexpr uint32_t runOperand(uint32_t op) {
    return op == kNoOperand ? kNoOperand : (operandIndex(op) << 4) | static_cast<uint32_t>(operandBase(op));
  }
  static constexpr uint32_t runIndex(uint32_t x) { return x >> 4; }
  static constexpr Base runBase(uint32_t x) { return static_cast<Base>(x & 3); }
  /// The operand `count` slots after x (consecutive arguments, a for loop's step).
  static constexpr uint32_t nextOperand(uint32_t x, uint32_t count = 1) { return x + (count << 4); }

  /// Where operands point: each base less its own number, so that at[x & 3] + x is the slot.
  struct OperandBases {
    char* at[4] = {nullptr, nullptr, nullptr, nullptr};
    void set(Base b, Value* p) {
      // In integers: an empty base (no constants) is a null pointer, which may not be offset.
      at[static_cast<uint32_t>(b)] =
          reinterpret_cast<char*>(reinterpret_cast<uintptr_t>(p) - static_cast<uint32_t>(b));
    }
    Value& operator()(uint32_t x) const {
      static_assert(sizeof(Value) == 16, "a slot is 16 bytes");
      return *reinterpret_cast<Value*>(at[x & 3] + x);
    }
    /// Operand x that is known to be a constant: no need to look its base up.
    const Value& constant(uint32_t x) const {
      return *reinterpret_cast<const Value*>(at[static_cast<uint32_t>(Base::Const)] + x);
    }
    /// Global slot i (IndexGet2's array).
    Value& global(uint32_t i) const { return reinterpret_cast<Value*>(at[0])[i]; }
  };

  void execute(uint32_t& pc);
  [[noreturn]] void badReturn();
  void doCallBuiltin(const Instr& in, uint32_t pc);
  void fuseMultiplyAdds();
  void doDim(const Instr& in);
  void doPrint(const Instr& in);
  void doFormat(const Instr& in);
  void doInput(const Instr& in);
  void doDataAppend(const Instr& in);
  bool checkpoint();
  Frame& pushFrame();
  void growFrames();
  bool forLoopStep(const Instr& in);
  /// Makes the stack hold at least `size` values (growing it moves the frame base).
  void ensureStack(size_t size) {
    if (size > stackSize_) [[unlikely]] growStack(size);
  }
  void growStack(size_t size);
  /// Points the frame base at the current frame (after a call, a return or a stack growth).
  void syncFrame() { bases_.set(Base::Frame, stack_.data() + base_); }
  bool compare(Cmp cmp, const Value& a, const Value& b, const Instr& in) const;
  bool compareOthers(Cmp cmp, const Value& a, const Value& b, const Instr& in) const;
  Value& element(const OperandBases& B, uint32_t arrOp, uint32_t idxOp, uint16_t count);
  Value& element2(const OperandBases& B, const Instr& in);
  Value& element2Slow(const Instr& in);
  [[noreturn]] void operandError(const Instr& in) const;
  [[noreturn]] void undefined(uint32_t op) const;
  [[noreturn]] void tooDeep() const;
  /// Notes for a runtime error: where each active gosub and sub call came from, innermost first.
  std::vector<Diagnostic> callChain() const;
  /// Line instructions from the last control transfer before `pc` up to `pc` (see run()).
  int64_t statementsBegun(uint32_t pc) const;
  /// Where the program reads variable `op` on the line of `at`, nearest `at` (an error about
  /// the variable points there); `at` when the compiler noted none.
  SourceLoc variableReadNear(SourceLoc at, uint32_t op) const;
  std::string slotName(uint32_t op) const;
  Value& arrayOperand(uint32_t op);
  size_t elementOffset(ArrObj& a, uint32_t arrOp, const Value* idx, uint32_t n);

  const Program& prog_;
  Machine& m_;
  /// prog_.code made ready to run (run()): operands re-encoded (runOperand), jump targets as
  /// byte offsets, and in finished code the interpreter's own forms (RB_OPCODES' last group).
  std::vector<Instr> code_;
  std::vector<Value> globals_;
  std::vector<Value> stack_;
  size_t stackSize_ = 0;  ///< stack_.size(), kept for the calls' check
  /// What a call of each sub needs, gathered from Program::subs when a run starts.
  struct SubEntry {
    const Instr* entry;
    uint32_t emptyFrom;  ///< the call empties slots emptyFrom..emptyTo-1 (SubInfo)
    uint32_t emptyTo;
    uint32_t stackNeed;  ///< stack slots the call makes sure of past the new frame base
  };
  std::vector<SubEntry> subEntries_;
  std::vector<Frame> frames_;  ///< storage of the call frames; the first depth_ are active
  uint32_t depth_ = 0;
  uint32_t depthCap_ = 0;      ///< frames that fit before growFrames(): at most maxCallDepth
  uint32_t base_ = 0;
  int32_t sub_ = -1;
  OperandBases bases_;
  static constexpr uint32_t kNoPc = UINT32_MAX;
  /// Where a runtime error being thrown belongs when that is not the current instruction (a
  /// sub that returned no value to an expression: the call's instruction); kNoPc otherwise.
  uint32_t errorPc_ = kNoPc;
  /// The variable a runtime error says has no value (undefined()), or kNoOperand.
  mutable uint32_t undefinedOp_ = kNoOperand;

  RunLimits limits_;
  uint64_t stepsDone_ = 0;   ///< steps counted before the current chunk
  int64_t chunk_ = 0;        ///< size of the current chunk
  int64_t stepsLeft_ = 0;    ///< steps left in the current chunk
  RunStatus stopStatus_ = RunStatus::Finished;
};

/// Formats print items with their separators: ',' joins, ';' puts a tab between items.
/// Returns true in `newline` unless the list ends with a separator.
std::string formatItems(const Value* items, uint32_t n, const std::vector<Tok>& seps, bool& newline);

}  // namespace rb
